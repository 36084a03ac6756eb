#pragma once

#include <string>
#include <utility>
#include <vector>

namespace kinematic_coverage::bench {

/// One `coverage_tool plan` run in a child process, as a user runs it.
struct CoverageToolRun {
  bool finished = false;  ///< exited within the timeout
  int exit_status = -1;
  double wall_s = 0.0;
  double peak_mb = 0.0;  ///< the child's peak resident memory (ru_maxrss)
  std::string output;    ///< standard output and error
};

/// Runs `tool plan mission --out dir [--set setting]...` in a child, its output to
/// `dir`.log, killed after `timeout_s`.
CoverageToolRun runPlan(const std::string& tool, const std::string& mission, const std::string& dir,
                        const std::vector<std::string>& settings, double timeout_s);

/// The stage lines of coverage_tool's output ("name: summary (seconds s)"): name, seconds.
std::vector<std::pair<std::string, double>> stageTimes(const std::string& output);

/// What a failed run said: its error line, else its last line (90 characters at most).
std::string firstWords(const std::string& output);

/// The planning time that coverage_tool reports ("planning took ... s"), 0 when none.
double planningSeconds(const std::string& output);

}  // namespace kinematic_coverage::bench
