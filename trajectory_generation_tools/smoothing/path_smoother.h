#pragma once

#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/path/path_primitive.h"
#include "trajectory_generation_tools/smoothing/boundary_edge_index.h"
#include "trajectory_generation_tools/smoothing/corner_waypoints.h"

namespace kinematic_coverage::core {

/// What smoothing a waypoint path did: turns_total counts the interior waypoints where the
/// heading changes by more than kStraightTurnTolerance (after dropping duplicates),
/// turns_smoothed those replaced by arcs, split by variant (counting corners);
/// kept_for_coverage the corners
/// that coverage-preserving smoothing left sharp where the fastest feasible choice was a
/// smoothing that would see less than the sharp turn.
struct SmoothingStatistics {
  int turns_total = 0;
  int turns_smoothed = 0;
  int inner = 0;
  int outer_bisector = 0;
  int outer_tangent = 0;
  int reverse_curve = 0;  ///< corners taken by reverse curves (two per curve; global only)
  int bulb = 0;           ///< corners taken by bulb turns (two per turn; global only)
  /// Arcs between straight legs made clothoid-arc-clothoid (`turn_curve: clothoid`).
  int clothoid = 0;
  int kept_for_coverage = 0;
};

/// A drivable path and how it was made.
struct SmoothedPath {
  /// Consecutive primitives, each starting where the previous one ends: segments (kNone),
  /// the arcs of each smoothed corner (tagged with their variant), and an in-place rotation
  /// (kNone) at every corner that stays sharp.
  std::vector<PathPrimitive> primitives;
  SmoothingStatistics statistics;
};

/// Algorithm 1 over a whole waypoint path (thesis 3.2): every corner in order, each corner's
/// A being the end of the previous smoothing where there was one; joining segments between.
class PathSmoother {
 public:
  /// Collisions are checked against the raw hull and holes of `free_area` (an empty hull:
  /// the unbounded plane), keeping `clearance` m from them (smoothing_clearance; 0: only
  /// no contact). Throws InvalidInputError for a turning radius that is not a positive
  /// finite number, a negative clearance or a non-finite coordinate.
  PathSmoother(const PolygonWithHoles& free_area, double turning_radius, double clearance = 0.0);

  /// The smoothed path through `waypoints`. Duplicate waypoints are dropped and straight
  /// ones (heading change <= kStraightTurnTolerance) merged into their legs
  /// (cornerWaypoints); fewer than two
  /// distinct waypoints give no primitives. Throws InvalidInputError for a non-finite
  /// coordinate.
  SmoothedPath smooth(const std::vector<Point2>& waypoints) const;
  /// The same from poses (their positions; headings follow from the legs).
  SmoothedPath smooth(const std::vector<Pose2>& waypoints) const;

 private:
  SmoothedPath build(const std::vector<Point2>& waypoints) const;

  BoundaryEdgeIndex index_;
  double radius_;
};

}  // namespace kinematic_coverage::core
