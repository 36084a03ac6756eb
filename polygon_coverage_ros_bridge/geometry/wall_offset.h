#pragma once

#include <memory>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// The offset free area (docs/REFERENCE.md, Geometry and input rules): one part, or
/// several where the offset splits the free area (a strait narrower than two wall
/// distances).
struct OffsetFreeArea {
  std::vector<PolygonWithHoles> parts;  ///< CCW hulls, CW holes; largest first
};

/// The least mitre limit (in wall distances), Clipper's: a mitre longer than twice the
/// distance (at a wall corner sharper than 60 degrees) is squared off.
constexpr double kMinMiterLimit = 2.0;

/// The default mitre limit (`offset_miter_limit`, in wall distances): a mitre longer than six
/// distances (at a wall corner sharper than 19 degrees) is squared off, its cut tangent to
/// the arc of the distance around the corner, still at least the wall distance from the
/// wall. A rough shore's needles throw unlimited mitres across the water, which cut the
/// offset free area into hundreds of parts that its lanes cannot reach; squared off at
/// kMinMiterLimit, the corners of 19 to 60 degrees change the cells of ordinary shores, and
/// 24 of planner_reference's 80 maps cost up to 34 % more (at 6, none more than 0.5 %).
constexpr double kDefaultMiterLimit = 6.0;

/// The largest mitre limit, the thesis preset's (its straight-skeleton offset has none; a
/// mitre is squared off only at a corner sharper than 0.11 degrees, so that a needle cannot
/// throw an offset corner across the map).
constexpr double kMaxMiterLimit = 1000.0;

/// How the offset edges meet around a wall's corner that bulges into the free area.
enum class OffsetCorners {
  /// Edges extended to a point (the straight-skeleton offset of the thesis's planner): inside
  /// the exact offset, short of it by the corner's mitre (a fifth of a square wall distance
  /// at a right angle, more at sharper corners).
  kMitred,
  /// Tangents to the arc around a corner sharper than kTangentStep, at most kTangentStep
  /// apart: inside the exact offset, close to it (a 50th of a square wall distance at a
  /// right angle) for a few vertices per sharp corner. Not yet the planner's: a
  /// trapezoidal decomposition makes cells of those vertices, and a shoreline's lanes
  /// grow longer.
  kTangent,
  /// Arcs of the distance around the corner, flattened to chords sagging at most
  /// kExactOffsetArcTolerance inside them: the exact offset, against which coverage is
  /// measured.
  kRound,
  /// Arcs around the corner flattened to chords that keep the distance (arcs and edges
  /// kRoundClearArcTolerance farther): inside the exact offset, short of it by at most that
  /// tolerance, in which gaps between parts are found (a path in it keeps the distance).
  kRoundClear,
};

/// The largest angle (radians) between successive tangents of kTangent corners: 30 degrees.
constexpr double kTangentStep = 0.5235987755982988;

/// Metres that a chord of a kRound corner may lie inside its arc (nearer the wall than the
/// wall distance): a quarter of the finest cell that coverage is measured on (0.9 cm on a
/// 9 m map), so that the reachable area's rim moves by less than the raster resolves, while
/// a chart's round offset keeps a few vertices per corner (at 0.5 mm, the round offset of a
/// 5 000-vertex chart took 2.5 s instead of 0.3 s).
constexpr double kExactOffsetArcTolerance = 2.5e-3;

/// Metres by which a kRoundClear offset falls short of the exact offset: a quarter of
/// kClearanceTolerance, so that a gap found in it at a distance half a tolerance below the
/// gap clearance is open wherever its exact clearance reaches the gap clearance.
constexpr double kRoundClearArcTolerance = 0.25e-3;

/// Metres within which a kRound or kRoundClear offset holds the mitred offset at the same
/// distance (whose edges lie on the exact offset's boundary), rounding included.
constexpr double kRoundOffsetReach = kClearanceTolerance + kRoundClearArcTolerance;

/// Computes the points of a cleaned free area at least `wall_distance` from the hull and
/// from every hole, with mitred offsets (the straight-skeleton offsets of the reference
/// planner: every offset edge parallel to its wall, corners extended to a point, up to
/// `miter_limit` wall distances, in [kMinMiterLimit, kMaxMiterLimit]): the hull
/// shrinks, each hole grows (the pockets its growth encloses filled: out of reach), and the
/// grown holes are subtracted from the shrunk hull, so that holes growing into each other
/// or into the hull merge. Offsets and Boolean operations are Clipper's, exact on integer
/// coordinates that resolve the map to about 1e-11 of its size. Every part of the result is
/// returned, the largest first, strictly simple (parts that touch at a point are apart).
/// Throws InvalidInputError when nothing is left.
OffsetFreeArea computeOffsetFreeArea(const PolygonWithHoles& free_area, double wall_distance,
                                     double miter_limit = kDefaultMiterLimit);

/// computeOffsetFreeArea of one free area at many distances (OffsetPartJoiner offsets the
/// same area at a dozen), with the rings converted once.
class WallOffset {
 public:
  /// `miter_limit` as computeOffsetFreeArea's, for the kMitred and kTangent corners.
  explicit WallOffset(const PolygonWithHoles& free_area, double miter_limit = kDefaultMiterLimit);
  ~WallOffset();
  WallOffset(const WallOffset&) = delete;
  WallOffset& operator=(const WallOffset&) = delete;

  /// computeOffsetFreeArea(free_area, distance), or with other `corners`; throws
  /// InternalError for a distance that is negative or not finite.
  OffsetFreeArea at(double distance, OffsetCorners corners = OffsetCorners::kMitred) const;

 private:
  struct Rings;
  std::unique_ptr<Rings> rings_;
  double miter_limit_;
};

/// The parts of `area` (hull and holes in either orientation) inside the axis-aligned box
/// [low, high], with Clipper's Boolean operations on the area's integer coordinates, as the
/// offsets: the windows that OffsetPartJoiner searches around each small part of a chart,
/// where an exact-kernel intersection with every edge of a 10 000-vertex shore cost a
/// fifth of a second per window (274 windows on a rough shore). Parts of zero area are
/// left out.
std::vector<PolygonWithHoles> clipToBox(const PolygonWithHoles& area, const Point2& low,
                                        const Point2& high);

/// The exact offset free area (docs/REFERENCE.md, Reachable area) around `offset_parts`
/// (mitred parts of the offset of `free_area` by `wall_distance`): the parts of the round
/// offset that hold one of them, so that coverage is measured against every point at least
/// the wall distance from the walls that the robot can reach, not only against the mitred
/// approximation the planner sweeps. Each mitred part lies inside one round part; a round
/// part holding none (beyond a gap the planner does not pass) stays out. With
/// `wall_distance` 0 the parts themselves. Throws InvalidInputError as computeOffsetFreeArea.
std::vector<PolygonWithHoles> exactOffsetParts(const PolygonWithHoles& free_area,
                                               double wall_distance,
                                               const std::vector<PolygonWithHoles>& offset_parts);

/// exactOffsetParts from the round offset (`round`: the kRound offset of the free area by
/// the wall distance), so that one round offset serves several sets of mitred parts.
std::vector<PolygonWithHoles> roundPartsHolding(std::vector<PolygonWithHoles> round,
                                                const std::vector<PolygonWithHoles>& offset_parts);

}  // namespace kinematic_coverage::core
