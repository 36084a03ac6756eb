#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "polygon_coverage_ros_bridge/gtsp/gtsp_instance.h"

namespace kinematic_coverage::core {
namespace testing {

/// A random asymmetric instance: nodes shuffled into `clusters` non-empty clusters of at
/// most max_cluster_size nodes, integer costs in [0, 100] (so ties occur), path mode when
/// path is true (start and goal drawn at random, distinct).
inline GtspInstance randomGtspInstance(std::mt19937& rng, int clusters, int max_cluster_size,
                                       bool path) {
  std::uniform_int_distribution<int> size(1, max_cluster_size);
  std::uniform_int_distribution<int> cost(0, 100);
  GtspInstance instance;
  std::vector<int> sizes(clusters);
  for (int& s : sizes) s = size(rng);
  for (int s : sizes) instance.node_count += s;
  std::vector<int> nodes(instance.node_count);
  for (int i = 0; i < instance.node_count; ++i) nodes[i] = i;
  std::shuffle(nodes.begin(), nodes.end(), rng);
  int next = 0;
  for (int s : sizes) {
    instance.clusters.emplace_back(nodes.begin() + next, nodes.begin() + next + s);
    next += s;
  }
  instance.costs.resize(static_cast<std::size_t>(instance.node_count) * instance.node_count);
  for (double& c : instance.costs) c = cost(rng);
  if (path) {
    std::uniform_int_distribution<int> pick(0, clusters - 1);
    instance.start_cluster = pick(rng);
    do {
      instance.goal_cluster = pick(rng);
    } while (instance.goal_cluster == instance.start_cluster);
  }
  return instance;
}

/// A planner-like path instance: node 0 is the start, node 1 the goal, then `cells`
/// clusters of `patterns` sweep patterns each (a pattern has a start point, an end point
/// and a length inside a random rectangle); the cost i -> j is the straight transition from
/// the end of i to the start of j plus the length of j, as in the planner's sweep graph.
inline GtspInstance randomSweepLikeInstance(std::mt19937& rng, int cells, int patterns) {
  std::uniform_real_distribution<double> coordinate(0.0, 100.0);
  std::uniform_real_distribution<double> half_size(2.0, 12.0);
  GtspInstance instance;
  instance.node_count = cells * patterns + 2;
  const std::size_t n = static_cast<std::size_t>(instance.node_count);
  std::vector<double> start_x(n), start_y(n), end_x(n), end_y(n), length(n, 0.0);
  for (std::size_t terminal = 0; terminal < 2; ++terminal) {
    start_x[terminal] = end_x[terminal] = coordinate(rng);
    start_y[terminal] = end_y[terminal] = coordinate(rng);
  }
  instance.clusters = {{0}, {1}};
  for (int cell = 0; cell < cells; ++cell) {
    const double cx = coordinate(rng);
    const double cy = coordinate(rng);
    const double w = half_size(rng);
    const double h = half_size(rng);
    instance.clusters.emplace_back();
    for (int k = 0; k < patterns; ++k) {
      const std::size_t node = 2 + static_cast<std::size_t>(cell * patterns + k);
      instance.clusters.back().push_back(static_cast<int>(node));
      const double sx = (k & 1) ? w : -w;
      const double sy = (k & 2) ? h : -h;
      const double angle = 0.4 * (k / 4);
      start_x[node] = cx + sx * std::cos(angle);
      start_y[node] = cy + sy;
      end_x[node] = cx - sx * std::cos(angle);
      end_y[node] = cy + (((k / 4) % 2) ? -sy : sy);
      length[node] = 4.0 * w * h / (2.0 + k / 4);
    }
  }
  instance.costs.assign(n * n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      if (i != j) {
        instance.costs[i * n + j] =
            std::hypot(end_x[i] - start_x[j], end_y[i] - start_y[j]) + length[j];
      }
    }
  }
  instance.start_cluster = 0;
  instance.goal_cluster = 1;
  return instance;
}

/// Brute force: every cluster order and every node choice (tiny instances only).
inline double bruteForceGtspCost(const GtspInstance& instance) {
  const int m = static_cast<int>(instance.clusters.size());
  std::vector<int> order(m);
  for (int c = 0; c < m; ++c) order[c] = c;
  double best = 1e300;
  do {
    if (instance.isPath()) {
      if (order.front() != instance.start_cluster || order.back() != instance.goal_cluster) {
        continue;
      }
    } else if (order.front() != 0) {
      continue;
    }
    std::vector<std::size_t> choice(m, 0);
    while (true) {
      std::vector<int> tour(m);
      for (int k = 0; k < m; ++k) tour[k] = instance.clusters[order[k]][choice[k]];
      best = std::min(best, gtspTourCost(instance, tour));
      int k = 0;
      while (k < m && ++choice[k] == instance.clusters[order[k]].size()) choice[k++] = 0;
      if (k == m) break;
    }
  } while (std::next_permutation(order.begin(), order.end()));
  return best;
}

}  // namespace testing
}  // namespace kinematic_coverage::core
