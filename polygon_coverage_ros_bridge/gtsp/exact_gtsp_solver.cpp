#include "polygon_coverage_ros_bridge/gtsp/exact_gtsp_solver.h"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace kinematic_coverage::core {
namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
/// Largest table (subsets x free nodes) the program may allocate: 400 MB of doubles.
constexpr double kMaxTableEntries = 5e7;
/// Free clusters above which a subset mask would not fit into the table index.
constexpr int kMaxFreeClusters = 26;
}  // namespace

ExactGtspSolver::ExactGtspSolver(const GtspInstance& instance) : instance_(instance) {
  const int m = static_cast<int>(instance.clusters.size());
  int last_cluster = -1;
  if (instance.isPath()) {
    first_cluster_ = instance.start_cluster;
    last_cluster = instance.goal_cluster;
  } else {
    first_cluster_ = 0;
    for (int c = 1; c < m; ++c) {
      if (instance.clusters[c].size() < instance.clusters[first_cluster_].size())
        first_cluster_ = c;
    }
  }
  for (int c = 0; c < m; ++c) {
    if (c == first_cluster_ || c == last_cluster) continue;
    cluster_begin_.push_back(static_cast<int>(free_nodes_.size()));
    for (int node : instance.clusters[c]) {
      free_nodes_.push_back(node);
      free_cluster_of_.push_back(static_cast<int>(free_clusters_.size()));
    }
    free_clusters_.push_back(c);
  }
  cluster_begin_.push_back(static_cast<int>(free_nodes_.size()));
}

double ExactGtspSolver::estimatedWork() const {
  const int k = static_cast<int>(free_clusters_.size());
  if (k > kMaxFreeClusters) return kInfinity;
  const double subsets = static_cast<double>(1u << k);
  const double n = static_cast<double>(free_nodes_.size());
  if (subsets * n > kMaxTableEntries) return kInfinity;
  const double programs =
      instance_.isPath() ? 1.0 : static_cast<double>(instance_.clusters[first_cluster_].size());
  return programs * subsets * std::max(1.0, n * n / 4.0);
}

void ExactGtspSolver::fillTable(const std::vector<double>& source) {
  const int k = static_cast<int>(free_clusters_.size());
  const std::size_t n = free_nodes_.size();
  const std::uint32_t subsets = 1u << k;
  table_.assign(static_cast<std::size_t>(subsets) * n, kInfinity);
  for (int c = 0; c < k; ++c) {
    double* row = &table_[(static_cast<std::size_t>(1u) << c) * n];
    for (int u = cluster_begin_[c]; u < cluster_begin_[c + 1]; ++u) row[u] = source[u];
  }
  for (std::uint32_t subset = 1; subset < subsets; ++subset) {
    const double* values = &table_[static_cast<std::size_t>(subset) * n];
    for (int c = 0; c < k; ++c) {
      if (!(subset & (1u << c))) continue;
      for (int u = cluster_begin_[c]; u < cluster_begin_[c + 1]; ++u) {
        const double value = values[u];
        if (value == kInfinity) continue;
        const double* costs = &local_costs_[static_cast<std::size_t>(u) * n];
        for (int next = 0; next < k; ++next) {
          if (subset & (1u << next)) continue;
          double* target = &table_[static_cast<std::size_t>(subset | (1u << next)) * n];
          for (int w = cluster_begin_[next]; w < cluster_begin_[next + 1]; ++w) {
            target[w] = std::min(target[w], value + costs[w]);
          }
        }
      }
    }
  }
}

std::vector<int> ExactGtspSolver::backtrack(int last) const {
  const std::size_t n = free_nodes_.size();
  std::uint32_t subset = (1u << free_clusters_.size()) - 1u;
  std::vector<int> order = {last};
  int v = last;
  while (subset != (1u << free_cluster_of_[v])) {
    const double value = table_[static_cast<std::size_t>(subset) * n + v];
    const std::uint32_t previous = subset & ~(1u << free_cluster_of_[v]);
    const double* values = &table_[static_cast<std::size_t>(previous) * n];
    int found = -1;
    for (std::size_t u = 0; u < n && found < 0; ++u) {
      if ((previous & (1u << free_cluster_of_[u])) &&
          values[u] + local_costs_[u * n + static_cast<std::size_t>(v)] == value) {
        found = static_cast<int>(u);
      }
    }
    v = found;
    subset = previous;
    order.push_back(v);
  }
  std::reverse(order.begin(), order.end());
  return order;
}

GtspSolution ExactGtspSolver::solve() {
  GtspSolution best = instance_.isPath() ? solvePath() : solveTour();
  if (!free_nodes_.empty()) best.cost = gtspTourCost(instance_, best.nodes);
  return best;
}

void ExactGtspSolver::fillLocalCosts() {
  const std::size_t n = free_nodes_.size();
  local_costs_.resize(n * n);
  for (std::size_t u = 0; u < n; ++u) {
    for (std::size_t w = 0; w < n; ++w) {
      local_costs_[u * n + w] = instance_.cost(free_nodes_[u], free_nodes_[w]);
    }
  }
}

GtspSolution ExactGtspSolver::solvePath() {
  const std::vector<int>& first = instance_.clusters[first_cluster_];
  const std::vector<int>& goal = instance_.clusters[instance_.goal_cluster];
  const std::size_t n = free_nodes_.size();
  GtspSolution best;
  best.cost = kInfinity;
  if (free_nodes_.empty()) {
    for (int s : first) {
      for (int g : goal) {
        if (instance_.cost(s, g) < best.cost) best = {{s, g}, instance_.cost(s, g)};
      }
    }
    return best;
  }
  fillLocalCosts();
  std::vector<double> source(n, kInfinity);
  std::vector<int> source_node(n, -1);
  for (std::size_t u = 0; u < n; ++u) {
    for (int s : first) {
      if (instance_.cost(s, free_nodes_[u]) < source[u]) {
        source[u] = instance_.cost(s, free_nodes_[u]);
        source_node[u] = s;
      }
    }
  }
  fillTable(source);
  const double* full = &table_[static_cast<std::size_t>((1u << free_clusters_.size()) - 1u) * n];
  double best_value = kInfinity;
  int best_last = -1;
  int best_goal = -1;
  for (std::size_t u = 0; u < n; ++u) {
    for (int g : goal) {
      const double value = full[u] + instance_.cost(free_nodes_[u], g);
      if (value < best_value) {
        best_value = value;
        best_last = static_cast<int>(u);
        best_goal = g;
      }
    }
  }
  const std::vector<int> order = backtrack(best_last);
  best.nodes = {source_node[order.front()]};
  for (int u : order) best.nodes.push_back(free_nodes_[u]);
  best.nodes.push_back(best_goal);
  return best;
}

GtspSolution ExactGtspSolver::solveTour() {
  const std::vector<int>& first = instance_.clusters[first_cluster_];
  const std::size_t n = free_nodes_.size();
  GtspSolution best;
  best.cost = kInfinity;
  if (free_nodes_.empty()) {
    for (int a : first) {
      if (instance_.cost(a, a) < best.cost) best = {{a}, instance_.cost(a, a)};
    }
    return best;
  }
  fillLocalCosts();
  std::vector<double> source(n);
  for (int a : first) {
    for (std::size_t u = 0; u < n; ++u) source[u] = instance_.cost(a, free_nodes_[u]);
    fillTable(source);
    const double* full = &table_[static_cast<std::size_t>((1u << free_clusters_.size()) - 1u) * n];
    double best_value = kInfinity;
    int best_last = -1;
    for (std::size_t u = 0; u < n; ++u) {
      const double value = full[u] + instance_.cost(free_nodes_[u], a);
      if (value < best_value) {
        best_value = value;
        best_last = static_cast<int>(u);
      }
    }
    if (best_value < best.cost) {
      best.nodes = {a};
      for (int u : backtrack(best_last)) best.nodes.push_back(free_nodes_[u]);
      best.cost = best_value;
    }
  }
  return best;
}

}  // namespace kinematic_coverage::core
