#pragma once

#include <memory>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// The offset free area (docs/REFERENCE.md, Geometry and input rules): one part, or
/// several where the offset splits the free area (a strait narrower than two wall
/// distances).
struct OffsetFreeArea {
  std::vector<PolygonWithHoles> parts;  ///< CCW hulls, CW holes; largest first
};

/// A mitre longer than this many wall distances (a corner sharper than 0.11 degrees) is
/// squared off at that length: still at least the wall distance from the wall, and a
/// needle cannot throw an offset corner across the map.
constexpr double kMiterLimit = 1000.0;

/// Computes the points of a cleaned free area at least `wall_distance` from the hull and
/// from every hole, with mitred offsets (the straight-skeleton offsets of the reference
/// planner: every offset edge parallel to its wall, corners extended to a point): the hull
/// shrinks, each hole grows (the pockets its growth encloses filled: out of reach), and the
/// grown holes are subtracted from the shrunk hull, so that holes growing into each other
/// or into the hull merge. Offsets and Boolean operations are Clipper's, exact on integer
/// coordinates that resolve the map to about 1e-11 of its size; a mitre longer than
/// kMiterLimit wall distances is squared off at that length. Every part of the result is
/// returned, the largest first, strictly simple (parts that touch at a point are apart).
/// Throws InvalidInputError when nothing is left.
OffsetFreeArea computeOffsetFreeArea(const PolygonWithHoles& free_area, double wall_distance);

/// computeOffsetFreeArea of one free area at many distances (OffsetPartJoiner offsets the
/// same area at a dozen), with the rings converted once.
class WallOffset {
 public:
  explicit WallOffset(const PolygonWithHoles& free_area);
  ~WallOffset();
  WallOffset(const WallOffset&) = delete;
  WallOffset& operator=(const WallOffset&) = delete;

  /// computeOffsetFreeArea(free_area, distance); throws InternalError for a distance that
  /// is negative or not finite.
  OffsetFreeArea at(double distance) const;

 private:
  struct Rings;
  std::unique_ptr<Rings> rings_;
};

}  // namespace kinematic_coverage::core
