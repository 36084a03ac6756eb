#pragma once

#include <cstddef>
#include <vector>

namespace kinematic_coverage::core {

/// Most nodes of a GTSPLIB file (GtsplibReader refuses a larger DIMENSION before it allocates
/// the file's dense cost matrix of 8 n^2 bytes: 275 MiB at the limit), and the nodes up to
/// which the planner keeps the cells' further lane directions (fitDirectionsToGtspLimit).
/// The planner's own instances have no node limit: its memory estimate
/// (planMemoryEstimateBytes) decides whether a plan can be made.
constexpr int kMaxGtspNodes = 6000;

/// A generalized travelling salesman instance: visit exactly one node of every cluster.
/// Cycle mode (start_cluster = goal_cluster = -1): a closed tour. Path mode (both >= 0,
/// distinct): a path that starts in start_cluster and ends in goal_cluster, without a
/// closing edge; the planner's directed sweep graph (thesis Sec. 3.3) is of this kind.
struct GtspInstance {
  int node_count = 0;
  /// A partition of 0..node_count-1; every cluster non-empty.
  std::vector<std::vector<int>> clusters;
  /// Row-major node_count * node_count; costs[i * node_count + j] is the cost of i -> j
  /// (asymmetric, finite, >= 0).
  std::vector<double> costs;
  int start_cluster = -1;
  int goal_cluster = -1;
  /// Optional (empty, or one entry per node): reverse_nodes[v] is the node of v's cluster
  /// that traverses v backwards (a sweep pattern run from its end to its start), or v
  /// itself. Local search then turns a stretch of the tour round with these nodes (2-opt,
  /// reversed or-opt), which keeps such moves cheap when costs are nearly symmetric under
  /// reversal, as the planner's are; empty: a reversed stretch keeps its nodes.
  std::vector<int> reverse_nodes;

  /// The cost of the edge from -> to.
  double cost(int from, int to) const {
    return costs[static_cast<std::size_t>(from) * static_cast<std::size_t>(node_count) +
                 static_cast<std::size_t>(to)];
  }
  /// True in path mode (start and goal clusters given).
  bool isPath() const { return start_cluster >= 0 && goal_cluster >= 0; }
};

/// A solution: one node per cluster in visiting order (path mode: a start-cluster node
/// first, a goal-cluster node last). In cycle mode the closing edge is included in cost.
struct GtspSolution {
  std::vector<int> nodes;
  double cost = 0.0;
  /// True when the safety cap (GtspOptions::time_limit_s) ended the search before its own
  /// stopping rule: the tour is the best found by then, and may be far from what the rule
  /// would have reached.
  bool time_capped = false;
};

/// Solver settings. A run is deterministic for a seed: the heuristic stops after a number
/// of generations without improvement; time_limit_s is only a safety cap.
struct GtspOptions {
  unsigned seed = 1;
  double time_limit_s = 60.0;
  /// Instances with at most this many clusters are solved exactly (subset dynamic program),
  /// unless the program's estimated work exceeds exact_work_limit.
  int exact_cluster_limit = 14;
  /// Estimated inner-loop steps above which the exact program is not attempted.
  double exact_work_limit = 1e9;
  /// Memetic population size; 0 chooses it from the cluster count: 10 + clusters / 2, at
  /// most max_population.
  int population_size = 0;
  int max_population = 100;  ///< cap of the population chosen from the cluster count
  /// Instances of more than 50 clusters only: a child's local search starts from its new
  /// edges, where a child of locally optimal parents can improve, instead of everywhere.
  /// 2 to 3 times faster on the planner's large path instances at the same tour quality;
  /// on GTSPLIB it trades some quality for time, so it is off by default.
  bool focused_search = false;
  /// Generations without improvement of the best tour after which the heuristic stops;
  /// 0 chooses it from the cluster count.
  int stall_generations = 0;
  /// Relative improvement of the best tour that every stall_generations generations must
  /// bring for the heuristic to go on (0: any improvement): bounds the long tail of ever
  /// smaller gains on instances of hundreds of clusters.
  double min_stall_gain = 0.0;
  /// Nearest clusters that local search tries as new neighbours of a cluster; 0 = default.
  int neighbour_count = 0;
  /// Threads on which the heuristic improves a generation's children (0: one per hardware
  /// thread). The tour found does not depend on it: children are drawn in one order and
  /// each local search depends on its child only.
  int threads = 0;
  /// Optional warm start for the heuristic: a valid tour in GtspSolution::nodes order.
  std::vector<int> warm_start;
};

/// Checks the instance (partition, matrix size, finite
/// non-negative costs, start/goal, reverse nodes within their clusters) and throws
/// InvalidInputError naming the first problem found.
void validateGtspInstance(const GtspInstance& instance);

/// Checks that nodes is a tour of the instance (one node per cluster, start first and goal
/// last in path mode) and throws InvalidInputError naming the problem otherwise.
void validateGtspTour(const GtspInstance& instance, const std::vector<int>& nodes);

/// The cost of a tour in visiting order, with the closing edge in cycle mode.
double gtspTourCost(const GtspInstance& instance, const std::vector<int>& nodes);

/// Solves the instance: exactly (ExactGtspSolver) up to options.exact_cluster_limit
/// clusters, with the memetic heuristic (MemeticGtspSolver) above. Throws
/// InvalidInputError for an invalid instance or warm start.
GtspSolution solveGtsp(const GtspInstance& instance, const GtspOptions& options);

}  // namespace kinematic_coverage::core
