#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// Which parts of a free area that the wall offset splits are planned (`offset_parts`).
enum class OffsetParts {
  kAll,      ///< every part, joined through the gaps between them (OffsetPartJoiner)
  kLargest,  ///< only the largest
};

/// A passage between two parts of the offset free area through a gap narrower than two
/// wall distances: a robot may pass it with less clearance than the wall distance.
struct OffsetGap {
  std::size_t from_part = 0;  ///< index into the parts: the side joined earlier
  std::size_t to_part = 0;    ///< the side this gap joins to it
  std::vector<Point2> path;   ///< from a boundary point of one part to one of the other
  Point2 narrowest_point = Point2::Zero();  ///< where the path's clearance is least
  double clearance_m = 0.0;                 ///< least distance from the path to the hull and holes
};

/// A part that no passage with at least the gap clearance joins to the start's part.
struct SealedPart {
  std::size_t part = 0;  ///< index into the parts
  /// The widest passage to it, when one keeps at least 2 % of the wall distance: its
  /// clearance is below the gap clearance. Empty: no such passage (a pinch point).
  std::optional<OffsetGap> widest_passage;
};

/// The offset free area's parts joined into one area in which transits are routed.
struct JoinedOffsetArea {
  /// The parts that the transits reach, joined by thin corridors along the gaps' paths
  /// (one polygon with holes); transitions between sweeps are routed in it.
  PolygonWithHoles route_area;
  /// Indices of the parts inside route_area (all of them unless a gap is sealed).
  std::vector<std::size_t> joined_parts;
  /// One per joined gap, each with at least the gap clearance.
  std::vector<OffsetGap> gaps;
  /// Parts that no passage with at least the gap clearance reaches from the joined ones.
  std::vector<SealedPart> sealed_parts;
};

/// Joins the parts of a split offset free area (docs/REFERENCE.md, Geometry and input
/// rules, Parts) by transits along each gap's widest path, through gaps with at least the
/// gap clearance (`gap_clearance`) only, in corridors that keep it: a part beyond narrower
/// gaps is sealed, named with its widest passage.
///
/// The free area is offset at decreasing distances below the wall distance; where two
/// groups of parts first fall into one offset component, the gap between them has about
/// that clearance (a maximin path: its narrowest point is as wide as the gap allows).
/// The transit is the shortest path between the groups inside that component, and a
/// corridor a small share of the clearance wide along it joins the parts into one area.
/// On a free area of thousands of vertices the offsets are taken in a window around each
/// smaller part first (a gap lies within two wall distances of its parts), and on the
/// whole area only when the windows leave a part apart.
class OffsetPartJoiner {
 public:
  /// `free_area` cleaned, `wall_distance` > 0 the distance that split it, `gap_clearance`
  /// in (0, wall_distance] the least clearance of a gap passed (kClearanceTolerance
  /// below it passes).
  OffsetPartJoiner(const PolygonWithHoles& free_area, double wall_distance, double gap_clearance);

  /// Joins `parts` (computeOffsetFreeArea's parts of the same free area and distance,
  /// largest first). The joined group is the one holding part `anchor` (the part the
  /// robot enters first).
  JoinedOffsetArea join(const std::vector<PolygonWithHoles>& parts, std::size_t anchor) const;

 private:
  const PolygonWithHoles& free_area_;
  double wall_distance_;
  double gap_clearance_;
};

}  // namespace kinematic_coverage::core
