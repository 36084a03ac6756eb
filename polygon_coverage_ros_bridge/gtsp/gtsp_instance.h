#pragma once

#include <cstddef>
#include <vector>

namespace kinematic_coverage::core {

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
  /// Memetic population size; 0 chooses it from the cluster count.
  int population_size = 0;
  /// Generations without improvement of the best tour after which the heuristic stops;
  /// 0 chooses it from the cluster count.
  int stall_generations = 0;
  /// Nearest clusters that local search tries as new neighbours of a cluster; 0 = default.
  int neighbour_count = 0;
  /// Optional warm start for the heuristic: a valid tour in GtspSolution::nodes order.
  std::vector<int> warm_start;
};

/// Checks the instance (partition, matrix size, finite non-negative costs, start/goal)
/// and throws InvalidInputError naming the first problem found.
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
