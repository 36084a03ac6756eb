#include "polygon_coverage_ros_bridge/gtsp/cluster_optimizer.h"

#include <algorithm>
#include <limits>

namespace kinematic_coverage::core {
namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
}  // namespace

ClusterOptimizer::ClusterOptimizer(const GtspInstance& instance) : instance_(instance) {}

void ClusterOptimizer::propagate(const std::vector<int>& clusters, std::size_t first_layer) {
  for (std::size_t l = first_layer; l < clusters.size(); ++l) {
    const std::vector<int>& previous = instance_.clusters[clusters[l - 1]];
    const std::vector<int>& current = instance_.clusters[clusters[l]];
    const std::size_t previous_offset = offset_[l - 1];
    // Row by row: the costs from one node to a cluster's nodes are usually adjacent.
    double* distance = distance_.data() + offset_[l];
    int* predecessor = predecessor_.data() + offset_[l];
    std::fill(distance, distance + current.size(), kInfinity);
    std::fill(predecessor, predecessor + current.size(), 0);
    for (std::size_t k = 0; k < previous.size(); ++k) {
      const double base = distance_[previous_offset + k];
      for (std::size_t j = 0; j < current.size(); ++j) {
        const double d = base + instance_.cost(previous[k], current[j]);
        if (d < distance[j]) {
          distance[j] = d;
          predecessor[j] = static_cast<int>(k);
        }
      }
    }
  }
}

double ClusterOptimizer::optimizePath(const std::vector<int>& clusters, std::vector<int>& nodes) {
  const std::size_t layers = clusters.size();
  offset_.assign(layers + 1, 0);
  for (std::size_t l = 0; l < layers; ++l) {
    offset_[l + 1] = offset_[l] + instance_.clusters[clusters[l]].size();
  }
  distance_.assign(offset_[layers], 0.0);
  predecessor_.assign(offset_[layers], 0);
  propagate(clusters, 1);
  const std::vector<int>& last = instance_.clusters[clusters.back()];
  double best = kInfinity;
  int index = 0;
  for (std::size_t j = 0; j < last.size(); ++j) {
    if (distance_[offset_[layers - 1] + j] < best) {
      best = distance_[offset_[layers - 1] + j];
      index = static_cast<int>(j);
    }
  }
  nodes.assign(layers, -1);
  for (std::size_t l = layers; l-- > 0;) {
    nodes[l] = instance_.clusters[clusters[l]][index];
    index = predecessor_[offset_[l] + index];
  }
  return best;
}

double ClusterOptimizer::optimizeCycle(const std::vector<int>& clusters, std::vector<int>& nodes) {
  const std::size_t m = clusters.size();
  // Anchor the cycle at its smallest cluster: one layered search per anchor node.
  std::size_t anchor = 0;
  for (std::size_t l = 1; l < m; ++l) {
    if (instance_.clusters[clusters[l]].size() < instance_.clusters[clusters[anchor]].size()) {
      anchor = l;
    }
  }
  rotated_.resize(m);
  for (std::size_t l = 0; l < m; ++l) rotated_[l] = clusters[(anchor + l) % m];
  offset_.assign(m + 1, 0);
  for (std::size_t l = 0; l < m; ++l) {
    offset_[l + 1] = offset_[l] + instance_.clusters[rotated_[l]].size();
  }
  distance_.assign(offset_[m], kInfinity);
  predecessor_.assign(offset_[m], 0);
  const std::vector<int>& anchor_nodes = instance_.clusters[rotated_[0]];
  const std::vector<int>& last = instance_.clusters[rotated_[m - 1]];
  auto closedCost = [&](std::size_t a, std::size_t* last_index) {
    for (std::size_t k = 0; k < anchor_nodes.size(); ++k) distance_[k] = k == a ? 0.0 : kInfinity;
    propagate(rotated_, 1);
    double best = kInfinity;
    for (std::size_t j = 0; j < last.size(); ++j) {
      const double d = distance_[offset_[m - 1] + j] + instance_.cost(last[j], anchor_nodes[a]);
      if (d < best) {
        best = d;
        *last_index = j;
      }
    }
    return best;
  };
  double best = kInfinity;
  std::size_t best_anchor = 0;
  std::size_t last_index = 0;
  if (m == 1) {
    for (std::size_t a = 0; a < anchor_nodes.size(); ++a) {
      const double d = instance_.cost(anchor_nodes[a], anchor_nodes[a]);
      if (d < best) {
        best = d;
        best_anchor = a;
      }
    }
    nodes.assign(1, anchor_nodes[best_anchor]);
    return best;
  }
  for (std::size_t a = 0; a < anchor_nodes.size(); ++a) {
    const double d = closedCost(a, &last_index);
    if (d < best) {
      best = d;
      best_anchor = a;
    }
  }
  best = closedCost(best_anchor, &last_index);
  std::vector<int> rotated_nodes(m);
  int index = static_cast<int>(last_index);
  for (std::size_t l = m; l-- > 1;) {
    rotated_nodes[l] = instance_.clusters[rotated_[l]][index];
    index = predecessor_[offset_[l] + index];
  }
  rotated_nodes[0] = anchor_nodes[best_anchor];
  nodes.assign(m, -1);
  for (std::size_t l = 0; l < m; ++l) nodes[(anchor + l) % m] = rotated_nodes[l];
  return best;
}

}  // namespace kinematic_coverage::core
