// libFuzzer target: the GTSPLIB parser (GtsplibReader::parse) on arbitrary text, and the
// GTSP solvers on the small instances it accepts: the exact dynamic program and the
// memetic heuristic. Properties: a parsed instance passes validateGtspInstance (the parser
// never hands on an instance the solver would reject); each solver's solution is a valid
// tour whose reported cost is its cost; the heuristic's tour costs no less than the exact
// optimum.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "fuzz/fuzz_check.h"
#include "polygon_coverage_ros_bridge/gtsp/gtsp_instance.h"
#include "polygon_coverage_ros_bridge/gtsp/gtsplib_reader.h"

namespace {

using kinematic_coverage::core::GtspInstance;
using kinematic_coverage::core::GtsplibProblem;
using kinematic_coverage::core::GtsplibReader;
using kinematic_coverage::core::GtspOptions;
using kinematic_coverage::core::GtspSolution;
using kinematic_coverage::core::InvalidInputError;
using kinematic_coverage::fuzz::fuzzCheck;

/// Instances up to these sizes are also solved, exactly and heuristically, keeping each
/// run in milliseconds.
constexpr int kMaxSolvedNodes = 16;
constexpr std::size_t kMaxSolvedClusters = 6;

bool sameCost(double a, double b) {
  return a == b || std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(a));
}

/// Solves the instance with `options`, checks the tour and its reported cost, and returns
/// the cost. `solver` names the solver in messages.
double solveAndCheck(const GtspInstance& instance, const GtspOptions& options,
                     const std::string& solver) {
  GtspSolution solution;
  try {
    solution = kinematic_coverage::core::solveGtsp(instance, options);
    kinematic_coverage::core::validateGtspTour(instance, solution.nodes);
  } catch (const InvalidInputError& error) {
    fuzzCheck(false, solver + " failed on a valid instance: " + error.what());
  }
  const double cost = kinematic_coverage::core::gtspTourCost(instance, solution.nodes);
  fuzzCheck(sameCost(cost, solution.cost), solver + " reported cost " +
                                               std::to_string(solution.cost) +
                                               " but the tour costs " + std::to_string(cost));
  return cost;
}

/// Checks the parsed instance and, when small, solves it and checks the tours.
void checkProblem(const GtsplibProblem& problem) {
  const GtspInstance& instance = problem.instance;
  try {
    kinematic_coverage::core::validateGtspInstance(instance);
  } catch (const InvalidInputError& error) {
    fuzzCheck(false, std::string("parsed instance is invalid: ") + error.what());
  }
  fuzzCheck(problem.type.empty() || problem.type == "GTSP" || problem.type == "AGTSP",
            "TYPE is " + problem.type);
  fuzzCheck(!instance.isPath(), "GTSPLIB instances are cycles");
  if (instance.node_count > kMaxSolvedNodes || instance.clusters.size() > kMaxSolvedClusters) {
    return;
  }
  GtspOptions exact;
  exact.time_limit_s = 5.0;
  const double optimum = solveAndCheck(instance, exact, "exact solver");
  GtspOptions heuristic = exact;
  heuristic.exact_cluster_limit = 0;
  const double found = solveAndCheck(instance, heuristic, "memetic solver");
  fuzzCheck(found >= optimum || sameCost(found, optimum),
            "memetic tour costs " + std::to_string(found) + ", below the exact optimum " +
                std::to_string(optimum));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  kinematic_coverage::fuzz::runExpectingOnlyInvalidInput([&] {
    std::istringstream in(text);
    checkProblem(GtsplibReader::parse(in, "fuzz.gtsp"));
  });
  return 0;
}
