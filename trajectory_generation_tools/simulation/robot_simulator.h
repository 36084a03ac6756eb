#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/simulation/robot_model.h"
#include "trajectory_generation_tools/simulation/tracking_error_statistics.h"
#include "trajectory_generation_tools/simulation/trajectory_follower.h"

namespace kinematic_coverage::core {

/// One recorded instant of a simulation (a row of `actual.csv`; docs/REFERENCE.md, File formats).
struct SimulationStep {
  double t = 0.0;  ///< s from the start
  Pose2 pose;      ///< the robot's position and heading
  /// m from the robot to the nearest point of the desired path (the polyline through the
  /// trajectory's poses).
  double tracking_error_m = 0.0;
  /// m: the robot's position less that nearest point, along x and along y.
  double tracking_error_x_m = 0.0;
  double tracking_error_y_m = 0.0;
  /// m from the robot to the trajectory piece that leads to the pose the controller targets
  /// (the segment from the pose before it; the first pose itself before any piece), which
  /// shows the lag and overshoot that the nearest point hides.
  double target_error_m = 0.0;
  /// m from the robot to the reference it tracks at t, |p(t) - p_d(t)| (controllers timed
  /// and pose_stream; 0 for the others).
  double time_matched_error_m = 0.0;
};

/// The tracking error split by axis (the thesis's Fig. 4.5c): over the simulation steps,
/// the mean and the largest absolute x and y components of the nearest-point error.
struct AxisErrorStatistics {
  double x_mean_m = 0.0;
  double y_mean_m = 0.0;
  double x_max_m = 0.0;
  double y_max_m = 0.0;
};

/// What a robot did on a trajectory.
struct SimulationResult {
  /// The start (t = 0) and then every simulation step, in order.
  std::vector<SimulationStep> steps;
  /// s until the last pose was reached: `traversal_time_s` of `coverage_tool simulate`.
  double traversal_time_s = 0.0;
  /// Over the simulation steps (the start left out); docs/REFERENCE.md, Metrics.
  TrackingErrorStatistics tracking;
  AxisErrorStatistics tracking_axes;
  TrackingErrorStatistics target_tracking;
  /// The time-matched errors, for controllers timed and pose_stream.
  std::optional<TrackingErrorStatistics> time_matched_tracking;
  /// The same errors sampled at kErrorSampleRate: the steps nearest to t = k / rate for
  /// k = 1, 2, ... up to the traversal time.
  TrackingErrorStatistics sampled_tracking;
  TrackingErrorStatistics sampled_target_tracking;
  std::optional<TrackingErrorStatistics> sampled_time_matched_tracking;
  /// Where the tracked reference asked for more than the vehicle can do.
  ReferenceExcess reference_excess;
};

/// Runs the robot model of TrajectoryFollower over a whole trajectory, as `coverage_tool
/// simulate` does: the robot starts at rest at the first pose, with its heading, and is
/// stepped every sim_dt until it has reached the last pose; every step records its pose
/// and its tracking errors.
class RobotSimulator {
 public:
  /// Most simulation steps of a run (sim_time_limit / sim_dt), which bounds its memory.
  static constexpr std::size_t kMaxSteps = 5000000;

  /// Throws InvalidInputError for a sim_time_limit of more than kMaxSteps steps of sim_dt.
  explicit RobotSimulator(const RobotModel& model);

  /// Simulates following `trajectory` (its poses in order; `times`, one per pose, for the
  /// timed controller). Throws InvalidInputError for no poses or a non-finite one, for the
  /// timed controller without times, and when the robot has not reached the last pose
  /// within sim_time_limit (a current faster than the robot, say).
  SimulationResult simulate(const std::vector<Pose2>& trajectory,
                            const std::vector<double>& times = {}) const;

 private:
  RobotModel model_;
};

}  // namespace kinematic_coverage::core
