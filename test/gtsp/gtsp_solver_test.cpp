#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/gtsp/exact_gtsp_solver.h"
#include "polygon_coverage_ros_bridge/gtsp/gtsp_instance.h"
#include "polygon_coverage_ros_bridge/gtsp/gtsplib_reader.h"
#include "test/gtsp/random_gtsp_instance.h"

namespace kinematic_coverage::core {
namespace {

using testing::bruteForceGtspCost;
using testing::randomGtspInstance;
using testing::randomSweepLikeInstance;

/// Asserts that a solution is a valid tour whose reported cost is its recomputed cost.
void expectValidSolution(const GtspInstance& instance, const GtspSolution& solution) {
  EXPECT_NO_THROW(validateGtspTour(instance, solution.nodes));
  EXPECT_DOUBLE_EQ(solution.cost, gtspTourCost(instance, solution.nodes));
  if (instance.isPath()) {
    const std::vector<int>& start = instance.clusters[instance.start_cluster];
    const std::vector<int>& goal = instance.clusters[instance.goal_cluster];
    EXPECT_NE(std::find(start.begin(), start.end(), solution.nodes.front()), start.end());
    EXPECT_NE(std::find(goal.begin(), goal.end(), solution.nodes.back()), goal.end());
  }
}

GtspOptions heuristicOnly(unsigned seed) {
  GtspOptions options;
  options.seed = seed;
  options.exact_cluster_limit = 0;
  return options;
}

TEST(ExactGtspSolver, EqualsBruteForceOnRandomInstances) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 60; ++trial) {
    const bool path = trial % 2 == 0;
    const int clusters = 2 + trial % 5;  // 2..6
    const GtspInstance instance = randomGtspInstance(rng, clusters, 3, path);
    const GtspSolution solution = ExactGtspSolver(instance).solve();
    expectValidSolution(instance, solution);
    EXPECT_DOUBLE_EQ(solution.cost, bruteForceGtspCost(instance)) << "trial " << trial;
  }
}

TEST(MemeticGtspSolver, EqualsExactProgramOnRandomInstancesUpToTenClusters) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 40; ++trial) {
    const bool path = trial % 2 == 1;
    const int clusters = 3 + trial % 8;  // 3..10
    const GtspInstance instance = randomGtspInstance(rng, clusters, 5, path);
    const GtspSolution exact = ExactGtspSolver(instance).solve();
    const GtspSolution heuristic = solveGtsp(instance, heuristicOnly(trial + 1));
    expectValidSolution(instance, exact);
    expectValidSolution(instance, heuristic);
    EXPECT_DOUBLE_EQ(heuristic.cost, exact.cost)
        << "trial " << trial << (path ? " path" : " cycle") << ", " << clusters << " clusters";
  }
}

TEST(MemeticGtspSolver, ValidToursOnLargerRandomInstances) {
  std::mt19937 rng(17);
  for (int trial = 0; trial < 6; ++trial) {
    const GtspInstance instance = randomGtspInstance(rng, 25 + 10 * trial, 6, trial % 2 == 0);
    const GtspSolution solution = solveGtsp(instance, heuristicOnly(3));
    expectValidSolution(instance, solution);
  }
}

TEST(MemeticGtspSolver, DeterministicForASeed) {
  std::mt19937 rng(23);
  const GtspInstance instance = randomGtspInstance(rng, 40, 5, true);
  const GtspSolution a = solveGtsp(instance, heuristicOnly(7));
  const GtspSolution b = solveGtsp(instance, heuristicOnly(7));
  EXPECT_EQ(a.nodes, b.nodes);
  EXPECT_EQ(a.cost, b.cost);
}

TEST(MemeticGtspSolver, TheTourDoesNotDependOnTheThreadCount) {
  // Children improved on several threads: the same tour as on one, with and without the
  // focused search and a warm start (whose population draws in batches).
  std::mt19937 rng(31);
  const std::vector<GtspInstance> instances = {randomGtspInstance(rng, 40, 5, false),
                                               randomSweepLikeInstance(rng, 70, 6)};
  for (const GtspInstance& instance : instances) {
    for (const bool focused : {false, true}) {
      GtspOptions options = heuristicOnly(11);
      options.focused_search = focused;
      options.threads = 1;
      const GtspSolution one = solveGtsp(instance, options);
      for (const int threads : {2, 3}) {
        options.threads = threads;
        const GtspSolution several = solveGtsp(instance, options);
        EXPECT_EQ(several.nodes, one.nodes) << threads << " threads, focused " << focused;
        EXPECT_EQ(several.cost, one.cost);
      }
      options.warm_start = one.nodes;
      options.threads = 1;
      const GtspSolution warm_one = solveGtsp(instance, options);
      options.threads = 2;
      EXPECT_EQ(solveGtsp(instance, options).nodes, warm_one.nodes);
    }
  }
}

TEST(MemeticGtspSolver, WarmStartIsNeverWorsened) {
  std::mt19937 rng(29);
  const GtspInstance instance = randomGtspInstance(rng, 30, 4, false);
  const GtspSolution first = solveGtsp(instance, heuristicOnly(1));
  GtspOptions options = heuristicOnly(2);
  options.warm_start = first.nodes;
  options.stall_generations = 1;
  const GtspSolution second = solveGtsp(instance, options);
  expectValidSolution(instance, second);
  EXPECT_LE(second.cost, first.cost);
}

TEST(MemeticGtspSolver, AnyTimeLimitGivesAValidTour) {
  std::mt19937 rng(37);
  const GtspInstance instance = randomGtspInstance(rng, 30, 4, true);
  for (double limit : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(),
                       std::numeric_limits<double>::infinity()}) {
    GtspOptions options = heuristicOnly(1);
    options.time_limit_s = limit;
    expectValidSolution(instance, solveGtsp(instance, options));
  }
}

TEST(MemeticGtspSolver, SaysWhenTheTimeCapEndedTheSearch) {
  std::mt19937 rng(41);
  const GtspInstance instance = randomGtspInstance(rng, 30, 4, true);
  const GtspSolution full = solveGtsp(instance, heuristicOnly(1));
  EXPECT_FALSE(full.time_capped);
  GtspOptions capped_options = heuristicOnly(1);
  capped_options.time_limit_s = 1e-9;
  const GtspSolution capped = solveGtsp(instance, capped_options);
  expectValidSolution(instance, capped);
  EXPECT_TRUE(capped.time_capped);
  // The exact solver has no cap.
  GtspOptions exact;
  exact.time_limit_s = 1e-9;
  const GtspInstance small = randomGtspInstance(rng, 6, 3, true);
  EXPECT_FALSE(solveGtsp(small, exact).time_capped);
}

TEST(MemeticGtspSolver, InvalidWarmStartIsRejected) {
  std::mt19937 rng(31);
  const GtspInstance instance = randomGtspInstance(rng, 20, 3, true);
  GtspOptions options = heuristicOnly(1);
  options.warm_start = {instance.clusters[0][0]};
  EXPECT_THROW(solveGtsp(instance, options), InvalidInputError);
}

TEST(GtspSolver, DegenerateInstances) {
  // One cluster, cycle: the cheapest self loop.
  GtspInstance single;
  single.node_count = 2;
  single.clusters = {{0, 1}};
  single.costs = {5, 1, 1, 3};
  for (int limit : {0, 14}) {
    GtspOptions options;
    options.exact_cluster_limit = limit;
    const GtspSolution solution = solveGtsp(single, options);
    EXPECT_EQ(solution.nodes, std::vector<int>({1}));
    EXPECT_DOUBLE_EQ(solution.cost, 3.0);
  }
  // Two clusters, path from cluster 1 to cluster 0.
  GtspInstance pair;
  pair.node_count = 3;
  pair.clusters = {{0}, {1, 2}};
  pair.costs = {0, 9, 9, 4, 0, 9, 2, 9, 0};
  pair.start_cluster = 1;
  pair.goal_cluster = 0;
  for (int limit : {0, 14}) {
    GtspOptions options;
    options.exact_cluster_limit = limit;
    const GtspSolution solution = solveGtsp(pair, options);
    EXPECT_EQ(solution.nodes, std::vector<int>({2, 0}));
    EXPECT_DOUBLE_EQ(solution.cost, 2.0);
  }
  // All costs zero, singleton clusters (a plain TSP).
  GtspInstance zero;
  zero.node_count = 30;
  for (int i = 0; i < 30; ++i) zero.clusters.push_back({i});
  zero.costs.assign(900, 0.0);
  const GtspSolution solution = solveGtsp(zero, heuristicOnly(1));
  expectValidSolution(zero, solution);
  EXPECT_EQ(solution.cost, 0.0);
}

TEST(GtspSolver, RejectsInvalidInstances) {
  auto base = [] {
    GtspInstance instance;
    instance.node_count = 3;
    instance.clusters = {{0}, {1, 2}};
    instance.costs.assign(9, 1.0);
    return instance;
  };
  auto expectRejected = [](const GtspInstance& instance, const std::string& fragment) {
    try {
      solveGtsp(instance, GtspOptions());
      ADD_FAILURE() << "accepted; expected: " << fragment;
    } catch (const InvalidInputError& error) {
      EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos) << error.what();
    }
  };
  GtspInstance instance = base();
  instance.clusters.push_back({});
  expectRejected(instance, "cluster 2 is empty");
  instance = base();
  instance.clusters = {{0, 1}, {1, 2}};
  expectRejected(instance, "node 1 is in cluster 0 and cluster 1");
  instance = base();
  instance.clusters = {{0}, {1}};
  expectRejected(instance, "node 2 is in no cluster");
  instance = base();
  instance.clusters = {{0}, {1, 5}};
  expectRejected(instance, "outside");
  instance = base();
  instance.costs.resize(8);
  expectRejected(instance, "cost matrix has 8 entries");
  instance = base();
  instance.costs[5] = std::numeric_limits<double>::quiet_NaN();
  expectRejected(instance, "cost 1 -> 2");
  instance = base();
  instance.costs[3] = -1.0;
  expectRejected(instance, "finite and >= 0");
  instance = base();
  instance.costs[3] = std::numeric_limits<double>::infinity();
  expectRejected(instance, "cost 1 -> 0");
  instance = base();
  instance.start_cluster = 0;
  expectRejected(instance, "both");
  instance = base();
  instance.start_cluster = 1;
  instance.goal_cluster = 1;
  expectRejected(instance, "must differ");
  instance = base();
  instance.start_cluster = 0;
  instance.goal_cluster = 2;
  expectRejected(instance, "out of range");
  instance = base();
  instance.node_count = 0;
  expectRejected(instance, "node_count");
  instance = base();
  instance.reverse_nodes = {0, 2};
  expectRejected(instance, "reverse_nodes has 2 entries, expected none or one per node (3)");
  instance = base();
  instance.reverse_nodes = {1, 1, 2};
  expectRejected(instance, "reverse node 1 of node 0 is not in its cluster 0");
}

TEST(GtspSolver, AMissingCostMatrixIsRefusedBeforeItIsRead) {
  // The planner's instances have no node limit; the matrix size is checked before any cost.
  GtspInstance instance;
  instance.node_count = 6001;
  instance.clusters = {{0}};
  try {
    solveGtsp(instance, GtspOptions());
    ADD_FAILURE() << "accepted an instance without costs";
  } catch (const InvalidInputError& error) {
    EXPECT_NE(std::string(error.what()).find("cost matrix has 0 entries, expected 6001*6001"),
              std::string::npos)
        << error.what();
  }
}

/// The reverse nodes of randomSweepLikeInstance: within each group of four patterns of a
/// direction, the one that runs between the same two points the other way.
std::vector<int> sweepLikeReverseNodes(const GtspInstance& instance, int patterns) {
  std::vector<int> reverse(static_cast<std::size_t>(instance.node_count));
  reverse[0] = 0;
  reverse[1] = 1;
  for (int node = 2; node < instance.node_count; ++node) {
    const int k = (node - 2) % patterns;
    const int flip = (k / 4) % 2 == 0 ? 1 : 3;  // straight across: swap x; diagonal: swap both
    reverse[node] = node - k + ((k & ~3) | ((k & 3) ^ flip));
  }
  return reverse;
}

TEST(GtspSolver, ReverseNodesKeepTheExactCostOfEveryMove) {
  // Any reverse map within the clusters is allowed (moves are costed with the nodes they
  // put in): heuristic tours stay valid and still reach the exact optimum on small instances.
  std::mt19937 rng(53);
  for (int trial = 0; trial < 40; ++trial) {
    GtspInstance instance = randomGtspInstance(rng, 3 + trial % 8, 4, trial % 2 == 0);
    instance.reverse_nodes.resize(static_cast<std::size_t>(instance.node_count));
    for (const std::vector<int>& cluster : instance.clusters) {
      for (int node : cluster) instance.reverse_nodes[node] = cluster[rng() % cluster.size()];
    }
    const GtspSolution exact = solveGtsp(instance, GtspOptions());
    const GtspSolution heuristic = solveGtsp(instance, heuristicOnly(trial + 1));
    expectValidSolution(instance, heuristic);
    EXPECT_DOUBLE_EQ(heuristic.cost, exact.cost) << "trial " << trial;
  }
}

TEST(GtspSolver, ReverseNodesOnPlannerLikeInstances) {
  std::mt19937 rng(59);
  for (int trial = 0; trial < 3; ++trial) {
    GtspInstance instance = randomSweepLikeInstance(rng, 12, 16);
    instance.reverse_nodes = sweepLikeReverseNodes(instance, 16);
    const GtspSolution exact = solveGtsp(instance, GtspOptions());
    const GtspSolution heuristic = solveGtsp(instance, heuristicOnly(1));
    expectValidSolution(instance, heuristic);
    EXPECT_NEAR(heuristic.cost, exact.cost, 1e-9 * exact.cost);
  }
  // As the planner solves large instances: reverse nodes and the focused search.
  GtspInstance large = randomSweepLikeInstance(rng, 58, 16);
  large.reverse_nodes = sweepLikeReverseNodes(large, 16);
  GtspOptions planner_options;
  planner_options.max_population = 30;
  planner_options.stall_generations = 5 + 60 / 3;
  planner_options.focused_search = true;
  const GtspSolution focused = solveGtsp(large, planner_options);
  expectValidSolution(large, focused);
  const GtspSolution same_seed = solveGtsp(large, planner_options);
  EXPECT_EQ(focused.nodes, same_seed.nodes);
}

// Speed is measured by bench/gtsp (docs/BENCHMARKS.md), not asserted here.
TEST(GtspSolver, PlannerSizedExactPathIsMatchedByTheHeuristic) {
  // 12 cells x 16 sweep patterns plus a start and a goal node: the planner's largest exact call.
  std::mt19937 rng(41);
  for (int trial = 0; trial < 3; ++trial) {
    const GtspInstance instance = randomSweepLikeInstance(rng, 12, 16);
    const GtspSolution exact = solveGtsp(instance, GtspOptions());
    expectValidSolution(instance, exact);
    const GtspSolution heuristic = solveGtsp(instance, heuristicOnly(1));
    expectValidSolution(instance, heuristic);
    EXPECT_NEAR(heuristic.cost, exact.cost, 1e-9 * exact.cost);
  }
}

// The planner's stopping rule (a minimum gain over the stall window): planner-sized
// instances keep the exact program's optimum, and a 90-cell one a tour within 0.5 % of
// the one found when any gain goes on, deterministically for a seed.
TEST(GtspSolver, MinimumStallGainKeepsTheToursOfPlannerLikeInstances) {
  std::mt19937 rng(53);
  GtspOptions with_gain = heuristicOnly(1);
  with_gain.focused_search = true;
  with_gain.min_stall_gain = 1e-3;
  for (int trial = 0; trial < 3; ++trial) {
    const GtspInstance instance = randomSweepLikeInstance(rng, 12, 16);
    const GtspSolution exact = solveGtsp(instance, GtspOptions());
    const GtspSolution heuristic = solveGtsp(instance, with_gain);
    expectValidSolution(instance, heuristic);
    EXPECT_NEAR(heuristic.cost, exact.cost, 1e-9 * exact.cost);
  }
  const GtspInstance large = randomSweepLikeInstance(rng, 90, 6);
  GtspOptions any_gain = with_gain;
  any_gain.min_stall_gain = 0.0;
  const GtspSolution reference = solveGtsp(large, any_gain);
  const GtspSolution bounded = solveGtsp(large, with_gain);
  expectValidSolution(large, bounded);
  EXPECT_LE(bounded.cost, 1.005 * reference.cost);
  EXPECT_EQ(solveGtsp(large, with_gain).nodes, bounded.nodes);
}

TEST(GtspSolver, ExactProgramOnUniformRandomCostsBoundsTheHeuristic) {
  // Uniform random costs make the program's pruning useless: its worst case at 14 clusters.
  std::mt19937 rng(43);
  GtspInstance instance = randomGtspInstance(rng, 14, 16, true);
  const GtspSolution exact = solveGtsp(instance, GtspOptions());
  expectValidSolution(instance, exact);
  EXPECT_GE(solveGtsp(instance, heuristicOnly(1)).cost, exact.cost - 1e-9);
}

TEST(GtspSolver, PlannerSizedHeuristicPathIsValid) {
  std::mt19937 rng(47);
  const GtspInstance instance = randomSweepLikeInstance(rng, 58, 16);
  expectValidSolution(instance, solveGtsp(instance, GtspOptions()));
}

TEST(GtspSolver, ReachesGtsplibOptima) {
  struct Case {
    const char* file;
    double optimum;
  };
  const std::string dir = std::string(KC_BENCH_DATA_DIR) + "/gtsplib/instances/";
  for (const Case& c : {Case{"symmetric/11eil51.gtsp", 174}, Case{"asymmetric/4br17.gtsp", 31},
                        Case{"symmetric/14st70.gtsp", 316}, Case{"asymmetric/14ft70.gtsp", 7707},
                        Case{"symmetric/20kroA100.gtsp", 9711}}) {
    const GtsplibProblem problem = GtsplibReader::readFile(dir + c.file);
    const GtspSolution exact = solveGtsp(problem.instance, GtspOptions());
    expectValidSolution(problem.instance, exact);
    EXPECT_EQ(exact.cost, c.optimum) << c.file;
    const GtspSolution heuristic = solveGtsp(problem.instance, heuristicOnly(1));
    expectValidSolution(problem.instance, heuristic);
    EXPECT_EQ(heuristic.cost, c.optimum) << c.file;
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
