#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace kinematic_coverage::core {

/// `coverage_tool evaluate MISSION.yaml --trajectory FILE.csv --out DIR [--set name=value
/// ...]`: the coverage of any trajectory, such as a robot's actual
/// poses. Loads the mission, validates and cleans its polygon as `plan` does (its start
/// and goal are not used), computes the offset free area, reads the trajectory
/// (PoseCsvReader: columns x, y, yaw required, t and kind optional) and writes
/// DIR/metrics.json: coverage_percent, coverage_loss_percent and reachable_coverage_percent
/// (measureTrajectoryCoverage, as `plan` measures its own trajectory, so that evaluating
/// plan's trajectory.csv gives plan's figures), pose_count, trajectory_length_m (the
/// polyline through the poses) and evaluation_time_s (validation, cleaning, wall offset
/// and coverage). Progress lines, warnings and notes as PlanCommand.
class EvaluateCommand {
 public:
  /// Usage text of the command.
  static std::string usage();

  /// Runs the command on its arguments (those after "evaluate"). Throws InvalidInputError
  /// for invalid input (a missing file, a bad CSV row, a non-finite number, no poses, ...);
  /// any other exception is an internal error.
  void run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) const;
};

}  // namespace kinematic_coverage::core
