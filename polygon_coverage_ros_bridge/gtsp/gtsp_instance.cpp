#include "polygon_coverage_ros_bridge/gtsp/gtsp_instance.h"

#include <cmath>
#include <sstream>
#include <string>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/gtsp/exact_gtsp_solver.h"
#include "polygon_coverage_ros_bridge/gtsp/memetic_gtsp_solver.h"

namespace kinematic_coverage::core {
namespace {

[[noreturn]] void reject(const std::string& message) {
  throw InvalidInputError("GTSP instance: " + message);
}

}  // namespace

void validateGtspInstance(const GtspInstance& instance) {
  const int n = instance.node_count;
  if (n <= 0) reject("node_count must be positive, got " + std::to_string(n));
  if (instance.clusters.empty()) reject("no clusters");
  const std::size_t expected = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  if (instance.costs.size() != expected) {
    std::ostringstream message;
    message << "cost matrix has " << instance.costs.size() << " entries, expected " << n << "*" << n
            << " = " << expected;
    reject(message.str());
  }
  std::vector<int> owner(static_cast<std::size_t>(n), -1);
  for (std::size_t c = 0; c < instance.clusters.size(); ++c) {
    if (instance.clusters[c].empty()) reject("cluster " + std::to_string(c) + " is empty");
    for (int node : instance.clusters[c]) {
      if (node < 0 || node >= n) {
        reject("cluster " + std::to_string(c) + " has node " + std::to_string(node) +
               " outside 0.." + std::to_string(n - 1));
      }
      if (owner[node] >= 0) {
        reject("node " + std::to_string(node) + " is in cluster " + std::to_string(owner[node]) +
               " and cluster " + std::to_string(c));
      }
      owner[node] = static_cast<int>(c);
    }
  }
  for (int node = 0; node < n; ++node) {
    if (owner[node] < 0) reject("node " + std::to_string(node) + " is in no cluster");
  }
  for (std::size_t i = 0; i < expected; ++i) {
    const double c = instance.costs[i];
    if (!std::isfinite(c) || c < 0.0) {
      std::ostringstream message;
      message << "cost " << static_cast<long long>(i / n) << " -> " << static_cast<long long>(i % n)
              << " is " << c << " (costs must be finite and >= 0)";
      reject(message.str());
    }
  }
  if (!instance.reverse_nodes.empty()) {
    if (instance.reverse_nodes.size() != static_cast<std::size_t>(n)) {
      reject("reverse_nodes has " + std::to_string(instance.reverse_nodes.size()) +
             " entries, expected none or one per node (" + std::to_string(n) + ")");
    }
    for (int node = 0; node < n; ++node) {
      const int reverse = instance.reverse_nodes[node];
      if (reverse < 0 || reverse >= n || owner[reverse] != owner[node]) {
        reject("reverse node " + std::to_string(reverse) + " of node " + std::to_string(node) +
               " is not in its cluster " + std::to_string(owner[node]));
      }
    }
  }
  const int m = static_cast<int>(instance.clusters.size());
  const bool has_start = instance.start_cluster >= 0;
  const bool has_goal = instance.goal_cluster >= 0;
  if (instance.start_cluster < -1 || instance.goal_cluster < -1 || has_start != has_goal) {
    reject("start_cluster and goal_cluster must both be -1 (cycle) or both >= 0 (path), got " +
           std::to_string(instance.start_cluster) + " and " +
           std::to_string(instance.goal_cluster));
  }
  if (has_start) {
    if (instance.start_cluster >= m || instance.goal_cluster >= m) {
      reject("start/goal cluster out of range 0.." + std::to_string(m - 1));
    }
    if (instance.start_cluster == instance.goal_cluster) {
      reject("start_cluster and goal_cluster must differ, both are " +
             std::to_string(instance.start_cluster));
    }
  }
}

void validateGtspTour(const GtspInstance& instance, const std::vector<int>& nodes) {
  const std::size_t m = instance.clusters.size();
  if (nodes.size() != m) {
    reject("tour has " + std::to_string(nodes.size()) + " nodes, expected one per cluster (" +
           std::to_string(m) + ")");
  }
  std::vector<int> owner(static_cast<std::size_t>(instance.node_count), -1);
  for (std::size_t c = 0; c < m; ++c) {
    for (int node : instance.clusters[c]) owner[node] = static_cast<int>(c);
  }
  std::vector<bool> seen(m, false);
  for (int node : nodes) {
    if (node < 0 || node >= instance.node_count) {
      reject("tour node " + std::to_string(node) + " does not exist");
    }
    if (seen[owner[node]]) {
      reject("tour visits cluster " + std::to_string(owner[node]) + " twice");
    }
    seen[owner[node]] = true;
  }
  if (instance.isPath() && (owner[nodes.front()] != instance.start_cluster ||
                            owner[nodes.back()] != instance.goal_cluster)) {
    reject("path tour must start in cluster " + std::to_string(instance.start_cluster) +
           " and end in cluster " + std::to_string(instance.goal_cluster));
  }
}

double gtspTourCost(const GtspInstance& instance, const std::vector<int>& nodes) {
  double total = 0.0;
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i) total += instance.cost(nodes[i], nodes[i + 1]);
  if (!instance.isPath() && !nodes.empty()) total += instance.cost(nodes.back(), nodes.front());
  return total;
}

GtspSolution solveGtsp(const GtspInstance& instance, const GtspOptions& options) {
  validateGtspInstance(instance);
  if (!options.warm_start.empty()) validateGtspTour(instance, options.warm_start);
  if (static_cast<int>(instance.clusters.size()) <= options.exact_cluster_limit) {
    ExactGtspSolver exact(instance);
    if (exact.estimatedWork() <= options.exact_work_limit) return exact.solve();
  }
  MemeticGtspSolver heuristic(instance, options);
  return heuristic.solve();
}

}  // namespace kinematic_coverage::core
