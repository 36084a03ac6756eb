#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace kinematic_coverage::core {

/// `coverage_tool replan MISSION.yaml --updated UPDATED.yaml --visited FILE.csv --out DIR
/// [--set name=value ...]` (docs/REFERENCE.md, coverage_tool): replans after obstacles moved
/// (Replanner: the remaining area by `replanning_method`, planned from the last visited
/// pose to the mission's goal) and writes the files of `plan` (metrics.json also with
/// `combined_coverage_percent`, the plot's heatmap showing visited and new together) and
/// DIR/remaining.yaml, the remaining parts as a list of polygons in the mission file's
/// `polygon:` form.
class ReplanCommand {
 public:
  /// Usage text of the command.
  static std::string usage();

  /// Runs the command on its arguments (those after "replan"). Throws InvalidInputError
  /// for invalid input or an impossible request; any other exception is an internal error.
  void run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) const;
};

}  // namespace kinematic_coverage::core
