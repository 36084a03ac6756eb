#pragma once

#include <Eigen/Geometry>
#include <cstddef>
#include <limits>
#include <map>
#include <utility>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "polygon_coverage_ros_bridge/route/boundary_grid.h"
#include "polygon_coverage_ros_bridge/route/segment_cost.h"

namespace kinematic_coverage::core {

/// Cheapest routes between points of a polygon with holes (the offset free area), for
/// the transitions between sweep patterns (shortest paths in the offset free
/// area by a visibility graph; Thesis section 3.1, its reference [10]).
///
/// Nodes are the vertices a route may bend at (reflex corners, pinch points); edges join
/// mutually visible nodes, weighted by SegmentCost, so a route costs the sum of its
/// segments' costs; all-pairs node costs are precomputed (Floyd-Warshall, or Dijkstra from
/// every node on a sparse graph). A query point's route goes straight when the segment
/// stays inside, else through the cheapest pair of nodes it and the other end see. With a
/// cost that increases with length, a node pair is an edge, and a node is seen from a query
/// point, only where the line is tangent to the walls at the node (mayBendAt): a far
/// sparser graph with the same cheapest routes. Boundary points and the nodes themselves
/// are valid query points. Points outside the polygon (beyond BoundaryGrid::tolerance())
/// throw InvalidInputError.
///
/// For many queries, register points once (addQueryPoint: each point's visible nodes and
/// its cost to every node are computed once), then queryCost / queryPath; costMatrix
/// does that for two point lists.
class VisibilityGraph {
 public:
  /// How the costs between nodes are found. The all-pairs tables give the cheapest costs, up
  /// to rounding; on demand, routes are the cheapest over edges of at most localRadius().
  enum class AllPairs {
    kByDensity,  ///< on demand above kOnDemandNodes; else Dijkstra below kSparseDensity,
                 ///< else Floyd-Warshall
    kFloydWarshall,
    kDijkstra,
    /// No all-pairs table: edges join only nodes within localRadius(), query points attach
    /// to the nodes they see within it (farther when they see none), and each query runs
    /// Dijkstra from its source until its targets are settled. A route is then a real path
    /// of the area whose cost the query reports exactly, though where the cheapest route
    /// has a straight stretch longer than the radius between corners it may bend once more.
    kOnDemand,
  };

  /// Builds the graph over `area` (hull and holes in either orientation; may have pinch
  /// points). Throws InvalidInputError for a ring BoundaryGrid rejects.
  VisibilityGraph(const PolygonWithHoles& area, const SegmentCost& segment_cost,
                  AllPairs all_pairs = AllPairs::kByDensity);

  /// Graphs with fewer edges than this share of all node pairs get their all-pairs costs by
  /// Dijkstra from every node, the others by Floyd-Warshall: measured on lake charts with
  /// every visible pair an edge, Dijkstra's n x edges relaxations cost about 7 times
  /// Floyd-Warshall's n^3 / 2 vectorized updates each (a 10 000-vertex chart, 3 739 nodes,
  /// 3 % of the pairs visible: 5 s against 11 s; a 2 000-vertex one, 19 %: Floyd-Warshall as
  /// fast). With the tangent pairs only, a chart's graph is far sparser (the 2 000-vertex
  /// chart: 0.8 % of the pairs, 0.37 s by Dijkstra).
  static constexpr double kSparseDensity = 1.0 / 16.0;

  /// Graphs of more nodes than this are searched on demand: an all-pairs table of 8 n^2
  /// bytes (128 MB here) and its n visibility tests per node stop paying off where most
  /// routes are short against the map (an archipelago of 2 000 islands: 14 080 nodes, a
  /// 1.6 GB table).
  static constexpr std::size_t kOnDemandNodes = 4000;

  /// On-demand graphs: the local radius is the one whose disk holds this many nodes on
  /// average over the area's bounding box (doubled until the nodes are connected).
  static constexpr double kLocalRadiusNodes = 200.0;

  /// The number of nodes and their positions.
  std::size_t nodeCount() const { return nodes_.size(); }
  const Point2& node(std::size_t k) const { return nodes_[k]; }

  /// The cheapest cost from node u to node w (infinity when unreachable): precomputed, or
  /// searched on demand.
  double nodeCost(std::size_t u, std::size_t w) const;

  /// True when routes are searched on demand (AllPairs::kOnDemand).
  bool onDemand() const { return on_demand_; }

  /// The longest edge of an on-demand graph (infinity with an all-pairs table).
  double localRadius() const { return local_radius_; }

  /// The number of node pairs that see each other (the graph's edges).
  std::size_t edgeCount() const;

  /// The area's boundary test, for callers that check segments the same way.
  const BoundaryGrid& boundary() const { return grid_; }

  /// True when the straight segment from a to b stays inside the area.
  bool visible(const Point2& a, const Point2& b) const;

  /// The cheapest route from a to b, both included ({a} when a == b); every point inside
  /// the area. Throws InvalidInputError when no route exists.
  std::vector<Point2> shortestPath(const Point2& a, const Point2& b) const;

  /// The cost of shortestPath(a, b) (infinity when no route exists).
  double cost(const Point2& a, const Point2& b) const;

  /// Query points located once and kept for later calls: for callers that ask about the
  /// same points many times (the coverage repair prices each patch at dozens of legs).
  /// Holds points of the graph it was first used with only.
  class PointCache;

  /// shortestPath(a, b) and cost(a, b), with a and b located once in `cache`.
  std::vector<Point2> shortestPath(const Point2& a, const Point2& b, PointCache* cache) const;
  double cost(const Point2& a, const Point2& b, PointCache* cache) const;

  /// Costs from every source to every target, row-major (sources.size() rows of
  /// targets.size()); each equals cost(source, target).
  std::vector<double> costMatrix(const std::vector<Point2>& sources,
                                 const std::vector<Point2>& targets) const;

  /// Points located once, with the nodes each sees, for one-to-many costs (costsFrom).
  class LocatedPoints;

  /// Locates every point (on every hardware thread). Throws InvalidInputError for a point
  /// outside the area.
  LocatedPoints locateAll(const std::vector<Point2>& points) const;

  /// The cost from located point `source` to each of `targets` (indices into `points`), each
  /// equal to cost() between the points, up to rounding.
  std::vector<double> costsFrom(const LocatedPoints& points, std::size_t source,
                                const std::vector<std::size_t>& targets) const;

  /// Registers a query point (for queryCost and queryPath) and returns its index.
  std::size_t addQueryPoint(const Point2& p);

  /// The number of registered query points.
  std::size_t queryPointCount() const { return query_points_.size(); }

  /// cost() between registered points i and j.
  double queryCost(std::size_t i, std::size_t j) const;

  /// shortestPath() between registered points i and j.
  std::vector<Point2> queryPath(std::size_t i, std::size_t j) const;

 private:
  /// A located query point: its boundary contact, the nodes it sees with the segment
  /// cost to each, and (when wanted) its cheapest cost to every node.
  struct QueryPoint {
    Point2 position;
    BoundaryGrid::Contact contact;
    std::vector<int> seen_nodes;
    std::vector<double> seen_costs;
    std::vector<double> node_costs;
  };

  /// The cheapest way between two query points: straight, or from `first` to `last` node.
  struct Route {
    double cost = 0.0;
    bool straight = true;
    int first = -1;
    int last = -1;
  };

  /// An on-demand search's result: per target its cost and the last node of its route
  /// (-1: straight), and (when asked for) the nodes of the first target's route in order.
  struct Search {
    std::vector<double> costs;
    std::vector<int> last;
    std::vector<int> route;
  };

  /// Gives the targets at a's position or seen straight from a their cost (a straight
  /// segment inside is the cheapest way: SegmentCost is subadditive), the others infinity;
  /// returns the others, which search() looks for.
  std::vector<std::size_t> straightTargets(const QueryPoint& a,
                                           const std::vector<const QueryPoint*>& targets,
                                           Search* result) const;
  /// On-demand graphs: Dijkstra from a's seen nodes until every target that a does not see
  /// has its cost settled; with `with_route`, the first target's route too.
  Search search(const QueryPoint& a, const std::vector<const QueryPoint*>& targets,
                bool with_route = false) const;
  /// On-demand graphs: edges between visible nodes within `radius`.
  void buildLocalEdges(double radius);
  /// True when every node is reachable from node 0 over the edges.
  bool nodesConnected() const;
  /// Buckets nodes in square cells of `cell` metres over `box` (the hull's bounds), for
  /// forNodesWithin; sets extent_.
  void indexNodes(const Eigen::AlignedBox2d& box, double cell);
  /// Calls visit(k) for every node k within `radius` of p, in a fixed order.
  template <typename Visit>
  void forNodesWithin(const Point2& p, double radius, Visit visit) const;
  /// True when a route from `point` may bend at node k: it sees k and does not run on into
  /// k's wall.
  bool seesNode(const QueryPoint& point, std::size_t k) const;

  /// Turns node_costs_, the segment costs of visible node pairs, into the cheapest costs
  /// between all pairs of nodes.
  void allPairsCosts(AllPairs method);
  void floydWarshall();
  void dijkstraFromEveryNode();

  /// True unless node k is a single corner and a route from `other` through it would run on
  /// into its wall: then the route, bending away from the wall, has a cheaper shortcut
  /// beside the node, so a cheapest route never comes that way when costs increase with
  /// length (a taut route is tangent to the walls at its bends: Lee's reduced visibility
  /// graph).
  bool mayBendAt(std::size_t k, const Point2& other) const;
  QueryPoint locate(const Point2& p) const;
  /// The point in `cache`, located (and with its visible nodes when `attached`).
  QueryPoint& cached(const Point2& p, bool attached, PointCache* cache) const;
  void attachNodes(QueryPoint* point, bool with_node_costs) const;
  /// All-pairs graphs: the point's cheapest cost to every node, through the nodes it sees.
  void addNodeCosts(QueryPoint* point) const;
  bool straightInside(const QueryPoint& a, const QueryPoint& b) const;
  Route bestRoute(const QueryPoint& a, const QueryPoint& b) const;
  std::vector<Point2> routePoints(const QueryPoint& a, const QueryPoint& b,
                                  const Route& route) const;
  std::vector<Point2> nodePath(int from, int to) const;
  std::vector<Point2> pathBetween(const QueryPoint& a, const QueryPoint& b) const;

  BoundaryGrid grid_;
  SegmentCost segment_cost_;
  bool tangent_only_;  ///< segment_cost_ increases with length: mayBendAt prunes
  std::vector<Point2> nodes_;
  std::vector<BoundaryGrid::Contact> node_contacts_;
  std::vector<double> node_costs_;  ///< nodeCount() x nodeCount(), row-major
  std::vector<std::vector<std::pair<int, double>>> neighbours_;  ///< visible nodes, costs
  std::vector<QueryPoint> query_points_;
  bool on_demand_ = false;
  double local_radius_ = std::numeric_limits<double>::infinity();
  Point2 index_origin_ = Point2::Zero();
  /// The length beyond which a radius reaches every node from every point of the area.
  double extent_ = 0.0;
  double index_cell_ = 1.0;
  std::size_t index_columns_ = 0;
  std::size_t index_rows_ = 0;
  std::vector<std::vector<int>> index_buckets_;  ///< node indices per cell, row-major
};

class VisibilityGraph::LocatedPoints {
 public:
  std::size_t size() const { return slot_.size(); }

 private:
  friend class VisibilityGraph;
  const QueryPoint& at(std::size_t i) const { return distinct_[slot_.at(i)]; }

  /// Each distinct position located once (a sweep pattern's end is another's start).
  std::vector<QueryPoint> distinct_;
  std::vector<std::size_t> slot_;  ///< the distinct point of each point asked for
};

class VisibilityGraph::PointCache {
 private:
  friend class VisibilityGraph;
  struct Entry {
    QueryPoint point;
    bool attached = false;
  };
  std::map<std::pair<double, double>, Entry> entries_;
};

}  // namespace kinematic_coverage::core
