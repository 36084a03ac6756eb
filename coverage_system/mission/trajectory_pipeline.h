#pragma once

#include <optional>
#include <vector>

#include "coverage_system/mission/trajectory_coverage.h"
#include "coverage_system/parameters/planner_parameters.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/trajectory/trajectory_generator.h"

namespace kinematic_coverage::core {

/// A waypoint path made drivable and measured, as every front end reports it.
struct MeasuredTrajectory {
  /// Smoothed (or segment-only), sampled and timed.
  GeneratedTrajectory trajectory;
  /// Its poses as trajectory.csv holds them (yaw wrapped into (-pi, pi]).
  std::vector<Pose2> poses;
  /// The sharp path's (unsmoothed) trajectory, the reference of what smoothing may lose;
  /// none when the trajectory is unsmoothed itself.
  std::optional<std::vector<Pose2>> sharp_poses;
  /// The coverage of `poses`, with what they fail to see of what `sharp_poses` see.
  TrajectoryCoverage coverage;
  /// Seconds spent making the trajectory (not its sharp path's or the measurement).
  double generation_s = 0.0;
};

/// Who made a pipeline's waypoints: a failure on the planner's own path is the package's
/// (InternalError naming the stage), on a path a user sent the user's (InvalidInputError).
enum class WaypointOrigin { kPlanner, kUser };

/// The trajectory half's one composition (docs/ARCHITECTURE.md): smooth, then sample, then
/// time (TrajectoryGenerator), then measure against the sharp path
/// (measureTrajectoryCoverage), with the options of one checked parameter set. coverage_tool,
/// the trajectory node and the benchmarks all make their trajectories with it.
class TrajectoryPipeline {
 public:
  /// `exact_parts`: the exact offset around the parts the robot reaches (a plan's
  /// exact_offset_parts, or reachableOffset's), which coverage-safe smoothing keeps and the
  /// coverage is measured on; it and `parameters` must outlive the pipeline. With
  /// WaypointOrigin::kPlanner, a failure on the waypoints is an InternalError naming the
  /// stage (smooth, trajectory or coverage), except SizeLimitError. Throws InvalidInputError
  /// for parameters out of range.
  TrajectoryPipeline(const PlannerParameters& parameters,
                     const std::vector<PolygonWithHoles>& exact_parts,
                     WaypointOrigin origin = WaypointOrigin::kPlanner);

  /// The trajectory through `waypoints` in the cleaned `free_area`, measured against its
  /// sharp path when `against_sharp_path`: trajectory(), sharpTrajectory(), measure().
  MeasuredTrajectory run(const std::vector<Pose2>& waypoints, const PolygonWithHoles& free_area,
                         bool against_sharp_path = true) const;

  /// The trajectory through `waypoints`: smoothed (or segment-only), sampled and timed.
  GeneratedTrajectory trajectory(const std::vector<Pose2>& waypoints,
                                 const PolygonWithHoles& free_area) const;

  /// The sharp path's (unsmoothed) trajectory through `waypoints`; none when the
  /// parameters do not smooth.
  std::optional<GeneratedTrajectory> sharpTrajectory(const std::vector<Pose2>& waypoints,
                                                     const PolygonWithHoles& free_area) const;

  /// The poses of a trajectory as trajectory.csv holds them (yaw wrapped into (-pi, pi]),
  /// so that `coverage_tool evaluate` of that file reports the figures measured on them.
  static std::vector<Pose2> writtenPoses(const std::vector<TrajectoryPose>& trajectory);

  /// The coverage of `poses` (with what they fail to see of `reference`'s), as run() measures.
  TrajectoryCoverage measure(const PolygonWithHoles& free_area, const std::vector<Pose2>& poses,
                             const std::optional<std::vector<Pose2>>& reference) const;

 private:
  /// `step()`, whose InvalidInputError is the package's failure in `stage` for the planner's
  /// waypoints.
  template <typename Step>
  auto failingAs(const char* stage, const Step& step) const;

  const PlannerParameters& parameters_;
  const std::vector<PolygonWithHoles>& exact_parts_;
  WaypointOrigin origin_;
  TrajectoryOptions options_;
  std::optional<TrajectoryOptions> sharp_options_;
};

}  // namespace kinematic_coverage::core
