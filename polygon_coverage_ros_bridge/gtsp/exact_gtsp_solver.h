#pragma once

#include <vector>

#include "polygon_coverage_ros_bridge/gtsp/gtsp_instance.h"

namespace kinematic_coverage::core {

/// Exact GTSP by dynamic programming over cluster subsets (Held-Karp generalized to
/// clusters): value(S, v) is the cheapest path from the fixed first cluster through the
/// clusters of S ending at node v. Path mode fixes the start cluster and appends the goal
/// cluster at the end; cycle mode anchors the tour at its smallest cluster, one program per
/// anchor node. Values live in one flat array indexed subset * free_nodes + node.
class ExactGtspSolver {
 public:
  /// The instance must be valid (validateGtspInstance) and outlive the solver.
  explicit ExactGtspSolver(const GtspInstance& instance);

  /// Estimated inner-loop steps of solve(); infinite when the table would not fit in
  /// memory (more than kMaxTableEntries values).
  double estimatedWork() const;

  /// The optimal tour.
  GtspSolution solve();

 private:
  /// The path instance: from the start cluster through every free cluster to the goal.
  GtspSolution solvePath();
  /// The tour instance: a cycle through every cluster, from each node of the first.
  GtspSolution solveTour();
  /// local_costs_: the costs between the free clusters' nodes.
  void fillLocalCosts();
  /// Runs the subset program from the given source costs (per free node) into table_.
  void fillTable(const std::vector<double>& source);
  /// Walks table_ back from free node `last` of the full subset; returns the free-node order.
  std::vector<int> backtrack(int last) const;

  const GtspInstance& instance_;
  int first_cluster_ = -1;  // start cluster (path) or anchor cluster (cycle)
  std::vector<int> free_clusters_;
  std::vector<int> free_nodes_;       // global ids, grouped by free cluster
  std::vector<int> free_cluster_of_;  // free cluster index of each free node
  std::vector<int> cluster_begin_;    // free node range of each free cluster
  std::vector<double> local_costs_;   // free node x free node
  std::vector<double> table_;
};

}  // namespace kinematic_coverage::core
