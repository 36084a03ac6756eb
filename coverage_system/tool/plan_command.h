#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace kinematic_coverage::core {

/// `coverage_tool plan MISSION.yaml --out DIR [--set name=value ...]` (docs/REFERENCE.md,
/// coverage_tool): loads the mission, validates and cleans the polygon, plans with CoveragePlanner,
/// smooths, samples and times the trajectory (TrajectoryGenerator), and writes
/// DIR/waypoints.csv, DIR/trajectory.csv, DIR/metrics.json (planning_time_s: validation
/// + cleaning + planning; cells, waypoint_count, path_length_m, time_cost_s, the
/// trajectory's figures and its coverage as measureTrajectoryCoverage gives it) and
/// DIR/plot.png (CoveragePlot: the heatmap, the paths, start, goal). One
/// progress line per stage goes to `out` as the stage finishes, and the written files are
/// named there last; warnings ("warning: ...") go to `err` only once the command has succeeded, so
/// that a failure prints just its one error line.
class PlanCommand {
 public:
  /// Usage text of the command.
  static std::string usage();

  /// Runs the command on its arguments (those after "plan"). Throws InvalidInputError for
  /// invalid input or an impossible request; any other exception is an internal error.
  void run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) const;
};

}  // namespace kinematic_coverage::core
