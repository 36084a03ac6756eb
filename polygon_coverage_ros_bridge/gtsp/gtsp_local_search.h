#pragma once

#include <chrono>
#include <memory>
#include <vector>

#include "polygon_coverage_ros_bridge/gtsp/cluster_optimizer.h"
#include "polygon_coverage_ros_bridge/gtsp/gtsp_instance.h"

namespace kinematic_coverage::core {

/// Local search for GTSP tours in the style of Gutin and Karapetyan's memetic algorithm:
/// cluster reinsertion with the best node of the moved cluster, or-opt (segments of 2 and
/// 3 clusters, both orientations), 2-opt with asymmetric costs (prefix sums of forward
/// and backward edge costs) and cluster optimization, repeated to a local optimum.
/// Candidate positions come from neighbour lists over clusters, so one pass is linear in
/// the cluster count, and don't-look bits skip clusters whose surroundings did not change
/// since they last failed to improve. A stretch that 2-opt or or-opt turns round takes the
/// instance's reverse nodes (GtspInstance::reverse_nodes) when it has them.
///
/// A tour is a sequence with fixed ends: in path mode start node, interior, goal node; in
/// cycle mode the anchor cluster's node at both ends. Moves only rearrange the interior;
/// the end nodes change only by cluster optimization.
class GtspLocalSearch {
 public:
  using Clock = std::chrono::steady_clock;

  /// instance must be valid and outlive the search; anchor_cluster is the cluster at both
  /// ends in cycle mode (ignored in path mode).
  GtspLocalSearch(const GtspInstance& instance, int anchor_cluster, int neighbour_count);

  /// Improves sequence in place to a local optimum (or until deadline); returns its cost.
  /// `focus`, when given (one flag per cluster), names the clusters whose surroundings
  /// changed since the sequence was last locally optimal (a child's new edges): moves start
  /// from those clusters only (and from where cluster optimization changes a node), and
  /// spread as moves succeed. Without it every cluster is looked at.
  double improve(std::vector<int>& sequence, Clock::time_point deadline,
                 const std::vector<char>* focus = nullptr);

  /// Replaces the nodes of sequence by the best ones for its cluster order; returns the cost.
  double optimizeClusters(std::vector<int>& sequence);

  /// The cost of a sequence (sum of its edges).
  double sequenceCost(const std::vector<int>& sequence) const;

  /// The cluster of a node.
  int clusterOf(int node) const { return cluster_of_[node]; }

 private:
  double cost(int from, int to) const { return instance_.cost(from, to); }
  /// The node that traverses `node` backwards (itself without reverse nodes).
  int reverse(int node) const { return reverse_nodes_.empty() ? node : reverse_nodes_[node]; }
  /// Touches the clusters around every position where sequence differs from previous_.
  void touchChanged(const std::vector<int>& sequence);
  /// Refreshes positions and prefix sums after a change of the sequence.
  void index(const std::vector<int>& sequence);
  /// Calls visit(position) for each position of cluster c (two for the cycle's anchor).
  template <typename Visit>
  void forEachPosition(int c, std::size_t length, Visit visit) const;
  /// Marks the cluster of node as worth looking at again by every move ("don't look bits").
  void touch(int node);
  /// Touches the nodes at positions first..last (clamped to the sequence).
  void touchRange(const std::vector<int>& sequence, std::ptrdiff_t first, std::ptrdiff_t last);
  bool reinsertPass(std::vector<int>& sequence);
  bool orOptPass(std::vector<int>& sequence);
  bool twoOptPass(std::vector<int>& sequence);

  const GtspInstance& instance_;
  const bool cycle_;
  const int anchor_cluster_;
  double epsilon_ = 0.0;
  std::vector<int> cluster_of_;
  const std::vector<int>& reverse_nodes_;
  /// Cluster distance, row-major: the cheapest edge in either direction between two clusters'
  /// nodes; a lower bound of every edge between them (shared by copies).
  std::shared_ptr<const std::vector<double>> cluster_distance_;
  std::vector<std::vector<int>> neighbours_;
  std::vector<int> position_;
  std::vector<double> edge_cost_;  ///< the cost of the edge from each position to the next
  std::vector<double> forward_prefix_;
  std::vector<double> backward_prefix_;  ///< the same stretch run backwards (reverse nodes)
  std::vector<int> clusters_buffer_;
  std::vector<int> nodes_buffer_;
  std::vector<int> scratch_;
  enum Move { kReinsert = 0, kOrOpt = 1, kTwoOpt = 2, kMoveCount = 3 };
  std::vector<char> look_[kMoveCount];  // per move and cluster: may still improve
  std::vector<int> previous_;
  std::vector<unsigned> edge_stamp_;  // marks edges already tried in one reinsertion
  unsigned stamp_ = 0;
  ClusterOptimizer optimizer_;
};

}  // namespace kinematic_coverage::core
