#pragma once

#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/smoothing/boundary_edge_index.h"
#include "trajectory_generation_tools/smoothing/global_smoothing_options.h"
#include "trajectory_generation_tools/smoothing/path_smoother.h"

namespace kinematic_coverage::core {

/// The global smoothing strategy (issue 10; the thesis's Chapter 5 names Algorithm 1's
/// corner-by-corner decisions as a limit): every corner's smoothing, among none (an
/// in-place rotation), inner, outer at the bisector boundary and outer at the tangent
/// intersection boundary (Alg. 2 to 8), each at a few radii between min_turning_radius and
/// turning_radius, is chosen jointly by dynamic programming over the corner sequence.
///
/// Feasibility is Algorithm 1's: a smoothing's arcs keep clear of the raw hull and holes,
/// start on the incoming leg and end on the outgoing one, and begin no sooner than the
/// previous corner's smoothing ends; the leg pieces between them are clear and in the free
/// area. The objective is the traversal time of the velocity model of INTERFACE section 5:
/// each arc chain driven at its speed limit min(v_max, yaw_rate_max * radius), a sharp
/// corner as stop, rotate at yaw_rate_max, go, and each leg piece in the fastest time
/// from the speed its previous primitive ends with to the one its next begins with under
/// a_max. Where a leg piece is too short for that speed change the cost is approximate;
/// TrajectoryGenerator compares the exact times with Algorithm 1's result.
class GlobalPathSmoother {
 public:
  /// Radii tried per corner when min_turning_radius < turning_radius, evenly spaced
  /// from turning_radius down to min_turning_radius.
  static constexpr int kRadiusLevels = 4;

  /// Collisions are checked against the raw hull and holes of `free_area` (an empty hull:
  /// the unbounded plane). Throws InvalidInputError for radii that are not positive and
  /// finite with min_turning_radius <= turning_radius, a velocity limit that is not
  /// positive and finite, or a non-finite coordinate.
  GlobalPathSmoother(const PolygonWithHoles& free_area, const GlobalSmoothingOptions& options);

  /// The smoothed path through `waypoints`, of the same form as PathSmoother's (duplicate
  /// and straight waypoints dropped, joining segments, arcs, rotations at sharp corners).
  /// Throws InvalidInputError for a non-finite coordinate.
  SmoothedPath smooth(const std::vector<Point2>& waypoints) const;
  /// The same from poses (their positions; headings follow from the legs).
  SmoothedPath smooth(const std::vector<Pose2>& waypoints) const;

 private:
  BoundaryEdgeIndex index_;
  GlobalSmoothingOptions options_;
  std::vector<double> radii_;
};

}  // namespace kinematic_coverage::core
