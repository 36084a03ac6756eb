#pragma once

#include <Eigen/Core>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <unordered_set>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "polygon_coverage_ros_bridge/gtsp/gtsp_instance.h"
#include "polygon_coverage_ros_bridge/route/segment_cost.h"
#include "polygon_coverage_ros_bridge/route/visibility_graph.h"

namespace kinematic_coverage::core {

/// The generalized TSP's transition costs on maps of thousands of sweep patterns, where
/// routing every pattern end to every pattern start (n^2 routes) would dominate planning.
/// Exact costs (routes through the visibility graph, Thesis section 3.1) join each cell's
/// patterns to those of its kCandidateCells nearest cells, the start to every pattern and
/// every pattern to the goal. Every other edge is estimated by its route through the best
/// of kLandmarks landmarks (points spread over the map): a real path, most often dearer than
/// the edge's own route, which a tour takes only where even that pays. makeExact then prices the
/// estimated edges that a tour uses and improves the tour again by local search where a price
/// changed, until the tour uses none: its cost is exact, and it is locally optimal on the costs
/// known (the candidate sets of LKH, with the other costs computed lazily). An estimate from below
/// (the straight segment) lured the search into round after round of pricing: 46 000 edges on a
/// rough shore of 419 cells, 20 s.
class LazyTransitionCosts {
 public:
  /// Nearest cells whose patterns a cell's patterns are routed to exactly (either way).
  static constexpr int kCandidateCells = 16;
  /// Points through which the other edges are estimated (each a search over the map).
  static constexpr int kLandmarks = 8;

  /// For every node v of `instance`: a transition from v starts at sources[v], one into v
  /// ends at targets[v] and then costs entering[v] more (the pattern entered). Node 0 is
  /// the start (its cluster 0), node 1 the goal (cluster 1): nothing enters the start or
  /// leaves the goal. Fills instance->costs (its clusters and node count given). Throws
  /// InvalidInputError for a point outside the graph's area.
  LazyTransitionCosts(const VisibilityGraph& graph, const SegmentCost& segment_cost,
                      std::vector<Point2> sources, std::vector<Point2> targets,
                      std::vector<double> entering, GtspInstance* instance);

  /// The edges whose cost is exact so far.
  std::size_t exactCount() const { return exact_count_; }

  /// Prices every estimated edge of the solution's tour, improves the tour by local search
  /// where a price changed, and repeats until the tour has no estimated edge; returns the
  /// tour with its exact cost. Local search stops at `deadline`, the pricing does not.
  GtspSolution makeExact(GtspInstance* instance, GtspSolution solution,
                         std::chrono::steady_clock::time_point deadline);

 private:
  /// Every node's route ends located once: the sources of all nodes but the goal, then the
  /// targets of all nodes but the start.
  struct RouteEnds {
    VisibilityGraph::LocatedPoints located;
    std::vector<std::size_t> source_index;  ///< per node, into located
    std::vector<std::size_t> target_index;  ///< per node, into located
    std::vector<std::size_t> every_source;  ///< the sources' indices, in node order
  };
  /// Per landmark: its cost from every node's source, and to every node's target plus the
  /// pattern entered.
  struct Landmarks {
    std::vector<std::vector<double>> from_landmark;
    std::vector<Eigen::ArrayXd> to_target;
  };

  RouteEnds locateEnds() const;
  Landmarks landmarkCosts(const RouteEnds& ends) const;
  /// Node v's row: through the best landmark, the candidates' routes, the straight segment
  /// where no landmark reaches; the goal's entry (filled before) kept.
  void fillRow(const RouteEnds& ends, const Landmarks& landmarks, std::size_t v,
               double* row_costs) const;
  /// True when the edge u -> v has its exact cost.
  bool exact(int u, int v) const;
  /// Prices the estimated edges of `sequence`; flags the clusters at both ends of an edge
  /// whose price differs from its estimate, and returns whether one did.
  bool priceEdges(const std::vector<int>& sequence, GtspInstance* instance,
                  std::vector<char>* changed_clusters);
  /// kLandmarks sources spread over the map by farthest-point sampling from the start, as
  /// indices into the located points (every_source[k]: the source of the k-th node that is
  /// not the goal).
  std::vector<std::size_t> chooseLandmarks(const std::vector<std::size_t>& every_source) const;
  /// Marks as candidates the kCandidateCells cells nearest each pattern cell, both ways,
  /// the start's cluster before every cell and the goal's after every cell.
  void chooseCandidates(const std::vector<std::vector<int>>& clusters);
  static std::uint64_t key(int u, int v) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(u)) << 32) |
           static_cast<std::uint32_t>(v);
  }

  const VisibilityGraph& graph_;
  SegmentCost segment_cost_;
  std::vector<Point2> sources_;
  std::vector<Point2> targets_;
  std::vector<double> entering_;
  std::vector<int> cluster_of_;
  std::size_t cluster_count_ = 0;
  std::vector<char> candidate_;  ///< cluster_count_ x cluster_count_, row-major
  std::unordered_set<std::uint64_t> priced_;
  std::size_t exact_count_ = 0;
};

}  // namespace kinematic_coverage::core
