#pragma once

#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/path/path_primitive.h"
#include "trajectory_generation_tools/smoothing/path_smoother.h"
#include "trajectory_generation_tools/trajectory/continuous_curvature_turns.h"
#include "trajectory_generation_tools/trajectory/trajectory_options.h"
#include "trajectory_generation_tools/trajectory/trajectory_pose.h"

namespace kinematic_coverage::core {

/// A drivable, timed trajectory and the figures reported about it (docs/REFERENCE.md, Metrics).
struct GeneratedTrajectory {
  std::vector<PathPrimitive> path;    ///< segments, arcs and in-place rotations
  std::vector<TrajectoryPose> poses;  ///< sampled, with t from the velocity model
  SmoothingStatistics statistics;     ///< turns_total, turns_smoothed, per variant
  double trajectory_length_m = 0.0;
  double traversal_time_s = 0.0;
  double max_curvature = 0.0;
  /// Smallest distance to the raw hull and holes over the primitives that lie in the free
  /// area, but for the first and last legs where they join a start or goal nearer than
  /// wall_distance to the offset free area (its shortest way in and out); infinity if none.
  double min_obstacle_clearance_m = 0.0;
  /// A point of the trajectory min_obstacle_clearance_m from the hull or a hole (within
  /// 1 cm); the origin where that is infinite.
  Point2 closest_approach = Point2::Zero();
};

/// Turns a waypoint path into a trajectory (Thesis sections 3.2 and 3.3): smoothing against
/// the raw hull and holes by `smoothing_strategy` (Algorithm 1, PathSmoother, or the
/// global GlobalPathSmoother, coverage-safe or not; with `smoothing: false`, segments with
/// in-place rotations), clothoid transitions into its turns with `turn_curve: clothoid`
/// (ContinuousCurvatureTurns), sampling, and timing with v_max, a_max and yaw_rate_max.
class TrajectoryGenerator {
 public:
  explicit TrajectoryGenerator(const TrajectoryOptions& options) : options_(options) {}

  /// The trajectory through `waypoints` in `free_area` (the cleaned free area); waypoints
  /// all at one place (one waypoint) give one pose there with the first one's heading.
  /// Throws InvalidInputError for no waypoints, non-finite waypoints or parameters out of
  /// range.
  GeneratedTrajectory generate(const std::vector<Pose2>& waypoints,
                               const PolygonWithHoles& free_area) const;

 private:
  /// The smoothed path by the strategy of the parameters. Global without coverage
  /// preservation is never slower than local: where local's exact time is lower (the
  /// global programme's cost is approximate on legs too short for a speed change), local's
  /// path is kept. Coverage-safe smoothing has no such fallback: Algorithm 1 may lose
  /// coverage.
  SmoothedPath smoothedPath(const std::vector<Pose2>& waypoints,
                            const PolygonWithHoles& free_area) const;

  /// `turn_curve: clothoid`: the smoothed `path` with its turns continuous in curvature,
  /// guarded by the coverage check of the strategy's sensor (none for Algorithm 1).
  ContinuousCurvaturePath continuousCurvature(const std::vector<PathPrimitive>& path,
                                              const std::vector<Pose2>& waypoints,
                                              const PolygonWithHoles& free_area) const;

  TrajectoryOptions options_;
};

}  // namespace kinematic_coverage::core
