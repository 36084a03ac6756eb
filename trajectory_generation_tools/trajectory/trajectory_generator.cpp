#include "trajectory_generation_tools/trajectory/trajectory_generator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "trajectory_generation_tools/smoothing/global_path_smoother.h"
#include "trajectory_generation_tools/trajectory/primitive_path_metrics.h"
#include "trajectory_generation_tools/trajectory/segment_path_builder.h"
#include "trajectory_generation_tools/trajectory/trajectory_sampler.h"
#include "trajectory_generation_tools/trajectory/trajectory_timing.h"

namespace kinematic_coverage::core {
namespace {

/// A primitive's ends count as in the free area within this distance (metres).
constexpr double kInsideTolerance = 1e-6;

/// turns_total of a segment path: its rotations that turn.
SmoothingStatistics segmentPathStatistics(const std::vector<PathPrimitive>& path) {
  SmoothingStatistics statistics;
  statistics.turns_total =
      static_cast<int>(std::count_if(path.begin(), path.end(), [](const PathPrimitive& p) {
        return p.kind() == PrimitiveKind::kRotation && p.turnAngle() > 0.0;
      }));
  return statistics;
}

}  // namespace

SmoothedPath TrajectoryGenerator::smoothedPath(const std::vector<Pose2>& waypoints,
                                               const PolygonWithHoles& free_area) const {
  const bool local_only = parameters_.smoothing_strategy == "local";
  if (!local_only && parameters_.smoothing_strategy != "global") {
    // coverage_safe: the global programme keeping the sharp path's coverage; Algorithm 1's
    // result, which may lose coverage, is no alternative.
    return GlobalPathSmoother(free_area, GlobalSmoothingOptions::fromParameters(parameters_))
        .smooth(waypoints);
  }
  SmoothedPath local = PathSmoother(free_area, parameters_.turning_radius).smooth(waypoints);
  if (local_only) return local;
  SmoothedPath global =
      GlobalPathSmoother(free_area, GlobalSmoothingOptions::fromParameters(parameters_))
          .smooth(waypoints);
  if (parameters_.coverage_preserving) return global;
  // The global programme's cost is exact except where a leg piece is too short for the
  // speed change between its neighbours; the exact times settle those few cases, so that
  // the global strategy is never slower than Algorithm 1.
  const TrajectoryTiming timing(parameters_);
  return timing.traversalTime(global.primitives) <= timing.traversalTime(local.primitives) ? global
                                                                                           : local;
}

GeneratedTrajectory TrajectoryGenerator::generate(const std::vector<Pose2>& waypoints,
                                                  const PolygonWithHoles& free_area) const {
  if (waypoints.empty()) {
    throw InvalidInputError("no waypoints: a trajectory needs at least one");
  }
  GeneratedTrajectory trajectory;
  if (parameters_.smoothing) {
    SmoothedPath smoothed = smoothedPath(waypoints, free_area);
    trajectory.path = std::move(smoothed.primitives);
    trajectory.statistics = smoothed.statistics;
  } else {
    trajectory.path = SegmentPathBuilder().build(waypoints);
    trajectory.statistics = segmentPathStatistics(trajectory.path);
  }
  if (trajectory.path.empty()) {
    // Every waypoint at one place: the robot stays there, turned as the first waypoint.
    const Pose2& only = waypoints.front();
    trajectory.path.push_back(PathPrimitive::rotation(
        only.position(), std::isfinite(only.yaw) ? wrapAngle(only.yaw) : 0.0, 0.0));
  }
  TrajectorySampler(parameters_).sample(trajectory.path, trajectory.poses);
  trajectory.traversal_time_s =
      TrajectoryTiming(parameters_).assignTimes(trajectory.path, trajectory.poses);
  trajectory.trajectory_length_m = primitivePathLength(trajectory.path);
  trajectory.max_curvature = primitivePathMaxCurvature(trajectory.path);

  std::vector<PathPrimitive> inside;
  for (const PathPrimitive& primitive : trajectory.path) {
    if (contains(free_area, primitive.start(), kInsideTolerance) &&
        contains(free_area, primitive.end(), kInsideTolerance)) {
      inside.push_back(primitive);
    }
  }
  trajectory.min_obstacle_clearance_m = primitivePathClearance(inside, free_area);
  return trajectory;
}

}  // namespace kinematic_coverage::core
