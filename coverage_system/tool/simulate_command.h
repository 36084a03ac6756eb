#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace kinematic_coverage::core {

/// `coverage_tool simulate MISSION.yaml --trajectory FILE.csv --out DIR [--set name=value
/// ...]`: a robot model (TrajectoryFollower, parameters from the
/// mission and --set) follows the trajectory's poses from rest at the first one
/// (RobotSimulator). Writes DIR/actual.csv (t,x,y,yaw at every simulation step, the start
/// first), DIR/metrics.json (exactly traversal_time_s, tracking_error_sum_m,
/// tracking_error_mean_m, tracking_error_percentiles_m and the coverage_percent and
/// coverage_loss_percent of the actual poses, measured as `evaluate` measures a
/// trajectory) and DIR/plot.png (the desired trajectory against the actual path coloured
/// by tracking error, over the heatmap of what the robot actually saw). The mission's
/// polygon is validated and cleaned as `plan` does; its start and goal are not used.
/// Progress lines go to `out`; warnings go to `err` only once the command has succeeded.
class SimulateCommand {
 public:
  /// Usage text of the command.
  static std::string usage();

  /// Runs the command on its arguments (those after "simulate"). Throws InvalidInputError
  /// for invalid input (a missing file, a bad CSV row, a parameter out of range) or an
  /// impossible request (the robot does not reach the last pose within sim_time_limit);
  /// any other exception is an internal error. Nothing is written when it throws.
  void run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) const;
};

}  // namespace kinematic_coverage::core
