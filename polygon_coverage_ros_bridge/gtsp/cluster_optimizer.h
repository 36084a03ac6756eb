#pragma once

#include <vector>

#include "polygon_coverage_ros_bridge/gtsp/gtsp_instance.h"

namespace kinematic_coverage::core {

/// "Cluster optimization" of Gutin and Karapetyan: for a fixed order of the clusters, the
/// best node of every cluster is a shortest path through the layered graph whose layers are
/// the clusters in that order. Exact for the order; reuses its buffers between calls.
class ClusterOptimizer {
 public:
  explicit ClusterOptimizer(const GtspInstance& instance);

  /// Best nodes for the open path through clusters[0], ..., clusters.back() (any node of
  /// the first and the last cluster may be chosen). Writes nodes, returns the path cost.
  double optimizePath(const std::vector<int>& clusters, std::vector<int>& nodes);

  /// Best nodes for the closed tour through the clusters in this cyclic order (closing
  /// edge included). Writes nodes in the same order as clusters, returns the tour cost.
  double optimizeCycle(const std::vector<int>& clusters, std::vector<int>& nodes);

 private:
  /// Layered shortest path from the given first-layer costs; fills distance_ and
  /// predecessor_ for layers 1..L-1 (offsets in offset_).
  void propagate(const std::vector<int>& clusters, std::size_t first_layer);

  const GtspInstance& instance_;
  std::vector<double> distance_;
  std::vector<int> predecessor_;
  std::vector<std::size_t> offset_;
  std::vector<int> rotated_;
};

}  // namespace kinematic_coverage::core
