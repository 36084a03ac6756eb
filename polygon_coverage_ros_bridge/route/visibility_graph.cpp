#include "polygon_coverage_ros_bridge/route/visibility_graph.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <utility>

#include "polygon_coverage_ros_bridge/base/indexed_min_heap.h"
#include "polygon_coverage_ros_bridge/base/parallel_for.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

constexpr double kUnreachable = std::numeric_limits<double>::infinity();

/// Each distinct position of a list of points once, in the order they first appear, and
/// for every point of the list the index of its position.
struct DistinctPositions {
  std::vector<Point2> positions;
  std::vector<std::size_t> slot;
};

DistinctPositions distinctPositions(const std::vector<Point2>& points) {
  DistinctPositions distinct;
  std::map<std::pair<double, double>, std::size_t> slot_of;
  for (const Point2& p : points) {
    const auto [it, inserted] =
        slot_of.emplace(std::make_pair(p.x(), p.y()), distinct.positions.size());
    if (inserted) distinct.positions.push_back(p);
    distinct.slot.push_back(it->second);
  }
  return distinct;
}

std::string describe(const Point2& p) {
  std::ostringstream text;
  text.precision(10);
  text << "(" << p.x() << ", " << p.y() << ")";
  return text.str();
}

}  // namespace

VisibilityGraph::VisibilityGraph(const PolygonWithHoles& area, const SegmentCost& segment_cost,
                                 AllPairs all_pairs)
    : grid_(area), segment_cost_(segment_cost), tangent_only_(segment_cost.increasesWithLength()) {
  for (int cluster : grid_.bendClusters()) {
    nodes_.push_back(grid_.clusterPosition(cluster));
    node_contacts_.push_back({cluster, {}});
  }
  const std::size_t n = nodes_.size();
  if (all_pairs == AllPairs::kOnDemand ||
      (all_pairs == AllPairs::kByDensity && n > kOnDemandNodes)) {
    on_demand_ = true;
    const Eigen::AlignedBox2d box = boundingBox(grid_.polygon().hull);
    const double area = std::max(box.sizes().prod(), 1e-12);
    double radius = std::sqrt(kLocalRadiusNodes * area / (M_PI * std::max<std::size_t>(n, 1)));
    indexNodes(box, radius);
    while (true) {
      buildLocalEdges(radius);
      if (radius >= extent_ || nodesConnected()) break;
      radius *= 2.0;
    }
    local_radius_ = radius;
    return;
  }
  // The visibility tests (most of the work) on every hardware thread, row u testing the
  // nodes after u; the graph is then built in the same order as one thread would.
  std::vector<std::vector<char>> visible(n);
  parallelFor(n, [&](std::size_t u) {
    visible[u].resize(n - u, 0);
    for (std::size_t w = u + 1; w < n; ++w) {
      visible[u][w - u] =
          mayBendAt(u, nodes_[w]) && mayBendAt(w, nodes_[u]) &&
          grid_.segmentInside(nodes_[u], node_contacts_[u], nodes_[w], node_contacts_[w]);
    }
  });
  node_costs_.assign(n * n, kUnreachable);
  neighbours_.assign(n, {});
  for (std::size_t u = 0; u < n; ++u) {
    node_costs_[u * n + u] = 0.0;
    for (std::size_t w = u + 1; w < n; ++w) {
      if (!visible[u][w - u]) continue;
      const double c = segment_cost_.of(nodes_[u], nodes_[w]);
      node_costs_[u * n + w] = node_costs_[w * n + u] = c;
      neighbours_[u].push_back({static_cast<int>(w), c});
      neighbours_[w].push_back({static_cast<int>(u), c});
    }
  }
  allPairsCosts(all_pairs);
}

void VisibilityGraph::indexNodes(const Eigen::AlignedBox2d& box, double cell) {
  index_origin_ = box.min();
  extent_ = box.diagonal().norm();
  index_cell_ = cell;
  index_columns_ = static_cast<std::size_t>(box.sizes().x() / cell) + 1;
  index_rows_ = static_cast<std::size_t>(box.sizes().y() / cell) + 1;
  index_buckets_.assign(index_columns_ * index_rows_, {});
  auto clampedCell = [&](double offset, std::size_t count) {
    return std::min(count - 1, static_cast<std::size_t>(std::max(0.0, offset / cell)));
  };
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    const Point2 offset = nodes_[k] - index_origin_;
    index_buckets_[clampedCell(offset.y(), index_rows_) * index_columns_ +
                   clampedCell(offset.x(), index_columns_)]
        .push_back(static_cast<int>(k));
  }
}

template <typename Visit>
void VisibilityGraph::forNodesWithin(const Point2& p, double radius, Visit visit) const {
  auto cellRange = [&](double centre, double origin, std::size_t count) {
    const double low = std::floor((centre - radius - origin) / index_cell_);
    const double high = std::floor((centre + radius - origin) / index_cell_);
    const double last = static_cast<double>(count - 1);
    return std::make_pair(static_cast<std::size_t>(std::clamp(low, 0.0, last)),
                          static_cast<std::size_t>(std::clamp(high, 0.0, last)));
  };
  const auto [column_low, column_high] = cellRange(p.x(), index_origin_.x(), index_columns_);
  const auto [row_low, row_high] = cellRange(p.y(), index_origin_.y(), index_rows_);
  const double squared = radius * radius;
  for (std::size_t row = row_low; row <= row_high; ++row) {
    for (std::size_t column = column_low; column <= column_high; ++column) {
      for (int k : index_buckets_[row * index_columns_ + column]) {
        if ((nodes_[k] - p).squaredNorm() <= squared) visit(static_cast<std::size_t>(k));
      }
    }
  }
}

void VisibilityGraph::buildLocalEdges(double radius) {
  const std::size_t n = nodes_.size();
  std::vector<std::vector<int>> visible(n);
  parallelFor(n, [&](std::size_t u) {
    forNodesWithin(nodes_[u], radius, [&](std::size_t w) {
      if (w > u && mayBendAt(u, nodes_[w]) && mayBendAt(w, nodes_[u]) &&
          grid_.segmentInside(nodes_[u], node_contacts_[u], nodes_[w], node_contacts_[w])) {
        visible[u].push_back(static_cast<int>(w));
      }
    });
    std::sort(visible[u].begin(), visible[u].end());
  });
  neighbours_.assign(n, {});
  for (std::size_t u = 0; u < n; ++u) {
    for (int w : visible[u]) {
      const double c = segment_cost_.of(nodes_[u], nodes_[w]);
      neighbours_[u].push_back({w, c});
      neighbours_[w].push_back({static_cast<int>(u), c});
    }
  }
}

bool VisibilityGraph::nodesConnected() const {
  if (nodes_.empty()) return true;
  std::vector<char> reached(nodes_.size(), 0);
  std::vector<int> stack = {0};
  reached[0] = 1;
  std::size_t count = 1;
  while (!stack.empty()) {
    const int u = stack.back();
    stack.pop_back();
    for (const auto& [w, c] : neighbours_[u]) {
      if (!reached[w]) reached[w] = 1, ++count, stack.push_back(w);
    }
  }
  return count == nodes_.size();
}

double VisibilityGraph::nodeCost(std::size_t u, std::size_t w) const {
  if (!on_demand_) return node_costs_[u * nodes_.size() + w];
  const QueryPoint from{nodes_[u], node_contacts_[u], {static_cast<int>(u)}, {0.0}, {}};
  const QueryPoint to{nodes_[w], node_contacts_[w], {static_cast<int>(w)}, {0.0}, {}};
  return search(from, {&to}).costs[0];
}

namespace {

/// Per-thread working arrays of on-demand searches, sized to the graph and left clean after
/// every search (only what it touched is reset): a search costs what it visits, not the
/// node count.
struct SearchScratch {
  std::vector<double> settled;
  std::vector<int> previous;
  std::vector<int> head;
  IndexedMinHeap queue{0};
  std::vector<int> touched;

  void fit(std::size_t n) {
    if (settled.size() == n) return;
    settled.assign(n, std::numeric_limits<double>::infinity());
    previous.assign(n, -1);
    head.assign(n, -1);
    queue = IndexedMinHeap(n);
    touched.clear();
  }
  void reset() {
    for (int u : touched) {
      settled[u] = std::numeric_limits<double>::infinity();
      previous[u] = -1;
      head[u] = -1;
    }
    touched.clear();
    queue.clear();
  }
};

}  // namespace

std::vector<std::size_t> VisibilityGraph::straightTargets(
    const QueryPoint& a, const std::vector<const QueryPoint*>& targets, Search* result) const {
  result->costs.assign(targets.size(), kUnreachable);
  result->last.assign(targets.size(), -1);
  std::vector<std::size_t> open;
  for (std::size_t t = 0; t < targets.size(); ++t) {
    const QueryPoint& b = *targets[t];
    if (b.position == a.position) {
      result->costs[t] = 0.0;
    } else if (straightInside(a, b)) {
      result->costs[t] = segment_cost_.of(a.position, b.position);
    } else {
      open.push_back(t);
    }
  }
  return open;
}

VisibilityGraph::Search VisibilityGraph::search(const QueryPoint& a,
                                                const std::vector<const QueryPoint*>& targets,
                                                bool with_route) const {
  Search result;
  const std::vector<std::size_t> open = straightTargets(a, targets, &result);
  if (open.empty()) return result;
  thread_local SearchScratch thread_scratch;
  SearchScratch& scratch = thread_scratch;
  scratch.fit(nodes_.size());
  // Each node is listed once, when first given a head or a cost, for the reset.
  auto touch = [&scratch](int u) {
    if (scratch.head[u] < 0 && scratch.settled[u] == kUnreachable) scratch.touched.push_back(u);
  };
  // The open targets that see each node, as linked lists over one array.
  struct Entry {
    std::size_t target;
    double cost;
    int next;
  };
  std::vector<Entry> entries;
  for (std::size_t t : open) {
    const QueryPoint& b = *targets[t];
    for (std::size_t i = 0; i < b.seen_nodes.size(); ++i) {
      const int u = b.seen_nodes[i];
      touch(u);
      entries.push_back({t, b.seen_costs[i], scratch.head[u]});
      scratch.head[u] = static_cast<int>(entries.size()) - 1;
    }
  }
  for (std::size_t i = 0; i < a.seen_nodes.size(); ++i) {
    const int u = a.seen_nodes[i];
    if (a.seen_costs[i] < scratch.settled[u]) {
      touch(u);
      scratch.settled[u] = a.seen_costs[i];
      scratch.queue.pushOrDecrease(u, a.seen_costs[i]);
    }
  }
  auto highestOpenCost = [&] {
    double highest = 0.0;
    for (std::size_t t : open) highest = std::max(highest, result.costs[t]);
    return highest;
  };
  double bound = kUnreachable;
  // Every open target is settled once the queue's least cost reaches the highest of their
  // costs; the bound is refreshed whenever it is reached, and every so often as they get
  // cheaper.
  constexpr std::size_t kBoundRefresh = 64;
  for (std::size_t pops = 1; !scratch.queue.empty(); ++pops) {
    const int u = scratch.queue.popMin();
    const double cost = scratch.settled[u];
    if (cost >= bound || pops % kBoundRefresh == 0) {
      bound = highestOpenCost();
      if (cost >= bound) break;
    }
    for (int e = scratch.head[u]; e >= 0; e = entries[e].next) {
      const double through = cost + entries[e].cost;
      if (through < result.costs[entries[e].target]) {
        result.costs[entries[e].target] = through;
        result.last[entries[e].target] = u;
      }
    }
    for (const auto& [w, c] : neighbours_[u]) {
      const double through = cost + c;
      if (through < scratch.settled[w]) {
        touch(w);
        scratch.settled[w] = through;
        scratch.previous[w] = u;
        scratch.queue.pushOrDecrease(w, through);
      }
    }
  }
  if (with_route && !targets.empty()) {
    for (int u = result.last[0]; u >= 0; u = scratch.previous[u]) result.route.push_back(u);
    std::reverse(result.route.begin(), result.route.end());
  }
  scratch.reset();
  return result;
}

bool VisibilityGraph::mayBendAt(std::size_t k, const Point2& other) const {
  return !tangent_only_ || !grid_.runsIntoCorner(node_contacts_[k].cluster, nodes_[k] - other);
}

std::size_t VisibilityGraph::edgeCount() const {
  std::size_t directed = 0;
  for (const auto& seen : neighbours_) directed += seen.size();
  return directed / 2;
}

void VisibilityGraph::allPairsCosts(AllPairs method) {
  const double n = static_cast<double>(nodes_.size());
  if (method == AllPairs::kByDensity) {
    const bool sparse = static_cast<double>(edgeCount()) < kSparseDensity * 0.5 * n * (n - 1.0);
    method = sparse ? AllPairs::kDijkstra : AllPairs::kFloydWarshall;
  }
  if (method == AllPairs::kDijkstra) {
    dijkstraFromEveryNode();
  } else {
    floydWarshall();
  }
  // Both leave the upper triangle; the lower one mirrors it, symmetric bit for bit.
  const std::size_t count = nodes_.size();
  for (std::size_t i = 0; i < count; ++i) {
    for (std::size_t j = 0; j < i; ++j) node_costs_[i * count + j] = node_costs_[j * count + i];
  }
}

void VisibilityGraph::floydWarshall() {
  // Floyd-Warshall over the per-segment costs, a row at a time (vectorized), on the upper
  // triangle only: the costs are symmetric, and an update of (i, j) and one of (j, i) add
  // the same two numbers, so the lower triangle would repeat the upper one bit for bit.
  // Row k is read whole: its part left of the diagonal is refreshed from column k first
  // (iteration k changes neither row k nor column k). Within an iteration each row reads
  // only itself and the copy of row k, so the rows are updated on every hardware thread.
  const std::size_t n = nodes_.size();
  Eigen::ArrayXd via_row(n);
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t j = 0; j < k; ++j) node_costs_[k * n + j] = node_costs_[j * n + k];
    via_row = Eigen::Map<const Eigen::ArrayXd>(&node_costs_[k * n], n);
    parallelFor(n - 1, [&](std::size_t i) {
      const double to_via = i < k ? node_costs_[i * n + k] : node_costs_[k * n + i];
      if (i == k || to_via == kUnreachable) return;
      const std::size_t right = n - i - 1;  // columns i + 1 to n - 1
      Eigen::Map<Eigen::ArrayXd> row(&node_costs_[i * n + i + 1], right);
      row = row.min(via_row.tail(right) + to_via);
    });
  }
}

void VisibilityGraph::dijkstraFromEveryNode() {
  // The edges in compressed rows, for locality; the sources on every hardware thread, each
  // writing its own row with its thread's queue. A node's cost is the least of
  // (neighbour's cost + edge) over the neighbours settled before it, whatever the order
  // of the queue's ties, so the rows do not depend on the queue.
  const std::size_t n = nodes_.size();
  std::vector<std::size_t> first_edge(n + 1, 0);
  std::vector<int> edge_target;
  std::vector<double> edge_cost;
  for (std::size_t u = 0; u < n; ++u) {
    for (const auto& [w, c] : neighbours_[u]) {
      edge_target.push_back(w);
      edge_cost.push_back(c);
    }
    first_edge[u + 1] = edge_target.size();
  }
  const std::size_t threads = parallelThreadCount(n);
  std::vector<IndexedMinHeap> queues(threads, IndexedMinHeap(n));
  parallelForOnThreads(n, threads, [&](std::size_t source, std::size_t thread) {
    double* row = &node_costs_[source * n];
    std::fill(row, row + n, kUnreachable);
    row[source] = 0.0;
    IndexedMinHeap& queue = queues[thread];
    queue.pushOrDecrease(static_cast<int>(source), 0.0);
    while (!queue.empty()) {
      const std::size_t u = static_cast<std::size_t>(queue.popMin());
      const double cost = row[u];
      for (std::size_t e = first_edge[u]; e < first_edge[u + 1]; ++e) {
        const double through = cost + edge_cost[e];
        const int w = edge_target[e];
        if (through < row[w]) {
          row[w] = through;
          queue.pushOrDecrease(w, through);
        }
      }
    }
  });
}

std::vector<Point2> VisibilityGraph::nodePath(int from, int to) const {
  // Follow the neighbour that continues a cheapest route; each step strictly lowers the
  // remaining cost, and a route never has more than nodeCount() nodes.
  const std::size_t n = nodes_.size();
  std::vector<Point2> path = {nodes_[from]};
  for (int u = from; u != to && path.size() <= n;) {
    int best = -1;
    double best_cost = kUnreachable;
    for (const auto& [w, c] : neighbours_[u]) {
      const double through = c + node_costs_[static_cast<std::size_t>(w) * n + to];
      if (through < best_cost) best_cost = through, best = w;
    }
    if (best < 0) break;
    u = best;
    path.push_back(nodes_[u]);
  }
  return path;
}

VisibilityGraph::QueryPoint VisibilityGraph::locate(const Point2& p) const {
  if (!grid_.contains(p)) {
    throw InvalidInputError("route point " + describe(p) + " lies outside the area");
  }
  QueryPoint point;
  point.position = p;
  point.contact = grid_.contactOf(p);
  return point;
}

bool VisibilityGraph::seesNode(const QueryPoint& point, std::size_t k) const {
  if (point.contact.cluster != node_contacts_[k].cluster && !mayBendAt(k, point.position)) {
    return false;
  }
  return grid_.segmentInside(point.position, point.contact, nodes_[k], node_contacts_[k]);
}

void VisibilityGraph::attachNodes(QueryPoint* point, bool with_node_costs) const {
  point->seen_nodes.clear();
  point->seen_costs.clear();
  point->node_costs.clear();
  auto attach = [&](std::size_t k) {
    if (!seesNode(*point, k)) return;
    point->seen_nodes.push_back(static_cast<int>(k));
    point->seen_costs.push_back(segment_cost_.of(point->position, nodes_[k]));
  };
  if (on_demand_) {
    // The nodes seen within the local radius; a point that sees none there looks farther.
    for (double radius = local_radius_; point->seen_nodes.empty(); radius *= 2.0) {
      forNodesWithin(point->position, radius, attach);
      if (radius >= extent_) break;
    }
    return;
  }
  for (std::size_t k = 0; k < nodes_.size(); ++k) attach(k);
  if (with_node_costs) addNodeCosts(point);
}

void VisibilityGraph::addNodeCosts(QueryPoint* point) const {
  const std::size_t n = nodes_.size();
  point->node_costs.assign(n, kUnreachable);
  for (std::size_t i = 0; i < point->seen_nodes.size(); ++i) {
    const double* row = &node_costs_[static_cast<std::size_t>(point->seen_nodes[i]) * n];
    const double to_node = point->seen_costs[i];
    for (std::size_t w = 0; w < n; ++w) {
      point->node_costs[w] = std::min(point->node_costs[w], to_node + row[w]);
    }
  }
}

bool VisibilityGraph::straightInside(const QueryPoint& a, const QueryPoint& b) const {
  return grid_.segmentInside(a.position, a.contact, b.position, b.contact);
}

VisibilityGraph::Route VisibilityGraph::bestRoute(const QueryPoint& a, const QueryPoint& b) const {
  if (a.position == b.position) return {0.0, true, -1, -1};
  if (on_demand_) {
    const Search found = search(a, {&b});
    const bool straight = found.last[0] < 0 && found.costs[0] < kUnreachable;
    return {found.costs[0], straight, -1, found.last[0]};
  }
  const std::size_t n = nodes_.size();
  Route via{kUnreachable, false, -1, -1};
  if (!a.node_costs.empty()) {
    for (std::size_t i = 0; i < b.seen_nodes.size(); ++i) {
      const double c = a.node_costs[b.seen_nodes[i]] + b.seen_costs[i];
      if (c < via.cost) via = {c, false, -1, b.seen_nodes[i]};
    }
  } else if (!b.node_costs.empty()) {
    // Costs are symmetric: b's cost to node u is u's cost to b.
    for (std::size_t i = 0; i < a.seen_nodes.size(); ++i) {
      const double c = a.seen_costs[i] + b.node_costs[a.seen_nodes[i]];
      if (c < via.cost) via = {c, false, a.seen_nodes[i], -1};
    }
  } else {
    for (std::size_t i = 0; i < a.seen_nodes.size(); ++i) {
      const double* row = &node_costs_[static_cast<std::size_t>(a.seen_nodes[i]) * n];
      for (std::size_t j = 0; j < b.seen_nodes.size(); ++j) {
        const double c = a.seen_costs[i] + row[b.seen_nodes[j]] + b.seen_costs[j];
        if (c < via.cost) via = {c, false, a.seen_nodes[i], b.seen_nodes[j]};
      }
    }
  }
  // No detour costs less than the straight segment (SegmentCost is subadditive), so a
  // detour that is not dearer needs no visibility test.
  const double straight = segment_cost_.of(a.position, b.position);
  if (via.cost <= straight) return via;
  if (straightInside(a, b)) return {straight, true, -1, -1};
  return via;
}

std::vector<Point2> VisibilityGraph::routePoints(const QueryPoint& a, const QueryPoint& b,
                                                 const Route& route) const {
  if (route.straight) {
    if (a.position == b.position) return {a.position};
    return {a.position, b.position};
  }
  if (route.cost == kUnreachable) {
    throw InvalidInputError("no route inside the area from " + describe(a.position) + " to " +
                            describe(b.position));
  }
  const std::size_t n = nodes_.size();
  int first = route.first;
  int last = route.last;
  double best = kUnreachable;
  if (first < 0) {
    for (std::size_t i = 0; i < a.seen_nodes.size(); ++i) {
      const double c = a.seen_costs[i] + node_costs_[a.seen_nodes[i] * n + last];
      if (c < best) best = c, first = a.seen_nodes[i];
    }
  } else if (last < 0) {
    for (std::size_t j = 0; j < b.seen_nodes.size(); ++j) {
      const double c = node_costs_[first * n + b.seen_nodes[j]] + b.seen_costs[j];
      if (c < best) best = c, last = b.seen_nodes[j];
    }
  }
  std::vector<Point2> path = {a.position};
  auto append = [&path](const Point2& p) {
    if (p != path.back()) path.push_back(p);
  };
  for (const Point2& p : nodePath(first, last)) append(p);
  append(b.position);
  return path;
}

std::vector<Point2> VisibilityGraph::pathBetween(const QueryPoint& a, const QueryPoint& b) const {
  if (!on_demand_) return routePoints(a, b, bestRoute(a, b));
  if (a.position == b.position) return {a.position};
  const Search found = search(a, {&b}, true);
  const Route route{found.costs[0], found.last[0] < 0 && found.costs[0] < kUnreachable, -1, -1};
  if (route.straight || route.cost == kUnreachable) return routePoints(a, b, route);
  std::vector<Point2> path = {a.position};
  for (int u : found.route) {
    if (nodes_[u] != path.back()) path.push_back(nodes_[u]);
  }
  if (b.position != path.back()) path.push_back(b.position);
  return path;
}

bool VisibilityGraph::visible(const Point2& a, const Point2& b) const {
  return straightInside(locate(a), locate(b));
}

std::vector<Point2> VisibilityGraph::shortestPath(const Point2& a, const Point2& b) const {
  PointCache cache;
  return shortestPath(a, b, &cache);
}

double VisibilityGraph::cost(const Point2& a, const Point2& b) const {
  PointCache cache;
  return cost(a, b, &cache);
}

VisibilityGraph::QueryPoint& VisibilityGraph::cached(const Point2& p, bool attached,
                                                     PointCache* cache) const {
  const auto key = std::make_pair(p.x(), p.y());
  auto it = cache->entries_.find(key);
  if (it == cache->entries_.end())
    it = cache->entries_.emplace(key, PointCache::Entry{locate(p)}).first;
  PointCache::Entry& entry = it->second;
  if (attached && !entry.attached) {
    attachNodes(&entry.point, false);
    entry.attached = true;
  }
  return entry.point;
}

std::vector<Point2> VisibilityGraph::shortestPath(const Point2& a, const Point2& b,
                                                  PointCache* cache) const {
  const QueryPoint& from = cached(a, false, cache);
  const QueryPoint& to = cached(b, false, cache);
  if (a == b) return {a};
  if (straightInside(from, to)) return {a, b};
  return pathBetween(cached(a, true, cache), cached(b, true, cache));
}

double VisibilityGraph::cost(const Point2& a, const Point2& b, PointCache* cache) const {
  const QueryPoint& from = cached(a, false, cache);
  const QueryPoint& to = cached(b, false, cache);
  if (a == b) return 0.0;
  if (straightInside(from, to)) return segment_cost_.of(a, b);
  return bestRoute(cached(a, true, cache), cached(b, true, cache)).cost;
}

std::vector<double> VisibilityGraph::costMatrix(const std::vector<Point2>& sources,
                                                const std::vector<Point2>& targets) const {
  // Each distinct point is located once; sources also get their cost to every node.
  std::vector<Point2> ends = sources;
  ends.insert(ends.end(), targets.begin(), targets.end());
  const DistinctPositions distinct = distinctPositions(ends);
  std::vector<QueryPoint> points;
  for (const Point2& p : distinct.positions) points.push_back(locate(p));
  const auto slots_begin = distinct.slot.begin();
  const auto sources_end = slots_begin + static_cast<std::ptrdiff_t>(sources.size());
  const std::vector<std::size_t> source_points(slots_begin, sources_end);
  const std::vector<std::size_t> target_points(sources_end, distinct.slot.end());
  std::vector<bool> is_source(points.size(), false);
  for (std::size_t p : source_points) is_source[p] = true;
  parallelFor(points.size(), [&](std::size_t i) { attachNodes(&points[i], is_source[i]); });

  // Costs between distinct points only, then spread over the requested rows and columns.
  auto slots = [&](const std::vector<std::size_t>& uses, std::vector<std::size_t>* distinct) {
    std::vector<std::size_t> slot(points.size(), points.size());
    for (std::size_t p : uses) {
      if (slot[p] == points.size()) {
        slot[p] = distinct->size();
        distinct->push_back(p);
      }
    }
    return slot;
  };
  std::vector<std::size_t> distinct_sources;
  std::vector<std::size_t> distinct_targets;
  const std::vector<std::size_t> source_slot = slots(source_points, &distinct_sources);
  const std::vector<std::size_t> target_slot = slots(target_points, &distinct_targets);
  // Routes are symmetric: a pair already computed the other way round, in an earlier row, is
  // reused. The entries so reused are never reuses themselves (their reverse lies in a later
  // row), so every other entry is computed first, rows on every hardware thread, and the
  // reuses copied after.
  const std::size_t columns = distinct_targets.size();
  std::vector<double> distinct_costs(distinct_sources.size() * columns);
  auto reversedKnown = [&](std::size_t row, std::size_t s, std::size_t t) {
    return target_slot[s] < columns && source_slot[t] < row;
  };
  std::vector<const QueryPoint*> target_list;
  for (std::size_t t : distinct_targets) target_list.push_back(&points[t]);
  parallelFor(distinct_sources.size(), [&](std::size_t row) {
    const std::size_t s = distinct_sources[row];
    if (on_demand_) {
      const Search found = search(points[s], target_list);
      std::copy(found.costs.begin(), found.costs.end(), &distinct_costs[row * columns]);
      return;
    }
    for (std::size_t column = 0; column < columns; ++column) {
      const std::size_t t = distinct_targets[column];
      if (!reversedKnown(row, s, t)) {
        distinct_costs[row * columns + column] = bestRoute(points[s], points[t]).cost;
      }
    }
  });
  if (!on_demand_) {
    parallelFor(distinct_sources.size(), [&](std::size_t row) {
      const std::size_t s = distinct_sources[row];
      for (std::size_t column = 0; column < columns; ++column) {
        const std::size_t t = distinct_targets[column];
        if (reversedKnown(row, s, t)) {
          distinct_costs[row * columns + column] =
              distinct_costs[source_slot[t] * columns + target_slot[s]];
        }
      }
    });
  }
  // Spread over the requested rows on every thread too: with thousands of points, these
  // copies take about as long as the routes.
  std::vector<double> result(sources.size() * targets.size());
  parallelFor(source_points.size(), [&](std::size_t i) {
    const double* row = &distinct_costs[source_slot[source_points[i]] * columns];
    double* out = &result[i * targets.size()];
    for (std::size_t j = 0; j < target_points.size(); ++j)
      out[j] = row[target_slot[target_points[j]]];
  });
  return result;
}

VisibilityGraph::LocatedPoints VisibilityGraph::locateAll(const std::vector<Point2>& points) const {
  DistinctPositions distinct = distinctPositions(points);
  LocatedPoints located;
  located.slot_ = std::move(distinct.slot);
  located.distinct_.resize(distinct.positions.size());
  parallelForInOrder(distinct.positions.size(), [&](std::size_t i) {
    located.distinct_[i] = locate(distinct.positions[i]);
    attachNodes(&located.distinct_[i], false);
  });
  return located;
}

std::vector<double> VisibilityGraph::costsFrom(const LocatedPoints& points, std::size_t source,
                                               const std::vector<std::size_t>& targets) const {
  const QueryPoint& a = points.at(source);
  std::vector<const QueryPoint*> target_list;
  for (std::size_t t : targets) target_list.push_back(&points.at(t));
  if (on_demand_) return search(a, target_list).costs;
  // The source's cost to every node once, then bestRoute for each target.
  QueryPoint from = a;
  addNodeCosts(&from);
  std::vector<double> costs;
  costs.reserve(targets.size());
  for (const QueryPoint* b : target_list) costs.push_back(bestRoute(from, *b).cost);
  return costs;
}

std::size_t VisibilityGraph::addQueryPoint(const Point2& p) {
  QueryPoint point = locate(p);
  attachNodes(&point, true);
  query_points_.push_back(std::move(point));
  return query_points_.size() - 1;
}

double VisibilityGraph::queryCost(std::size_t i, std::size_t j) const {
  return bestRoute(query_points_.at(i), query_points_.at(j)).cost;
}

std::vector<Point2> VisibilityGraph::queryPath(std::size_t i, std::size_t j) const {
  return pathBetween(query_points_.at(i), query_points_.at(j));
}

}  // namespace kinematic_coverage::core
