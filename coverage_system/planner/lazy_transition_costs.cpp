#include "coverage_system/planner/lazy_transition_costs.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

#include "polygon_coverage_ros_bridge/base/parallel_for.h"
#include "polygon_coverage_ros_bridge/gtsp/gtsp_local_search.h"

namespace kinematic_coverage::core {
namespace {

constexpr int kStartNode = 0;
constexpr int kGoalNode = 1;
constexpr int kStartCluster = 0;
constexpr int kGoalCluster = 1;
/// Nearest clusters that local search tries as a cluster's new neighbours (the memetic
/// solver's default).
constexpr int kLocalSearchNeighbours = 20;
constexpr double kUnknown = std::numeric_limits<double>::infinity();

}  // namespace

LazyTransitionCosts::LazyTransitionCosts(const VisibilityGraph& graph,
                                         const SegmentCost& segment_cost,
                                         std::vector<Point2> sources, std::vector<Point2> targets,
                                         std::vector<double> entering, GtspInstance* instance)
    : graph_(graph),
      segment_cost_(segment_cost),
      sources_(std::move(sources)),
      targets_(std::move(targets)),
      entering_(std::move(entering)) {
  const std::size_t n = static_cast<std::size_t>(instance->node_count);
  cluster_of_.assign(n, -1);
  for (std::size_t c = 0; c < instance->clusters.size(); ++c) {
    for (int v : instance->clusters[c]) cluster_of_[v] = static_cast<int>(c);
  }
  chooseCandidates(instance->clusters);
  const RouteEnds ends = locateEnds();
  instance->costs.assign(n * n, 0.0);
  // Into the goal: one search from it, routes costing the same either way.
  const std::vector<double> to_goal =
      graph_.costsFrom(ends.located, ends.target_index[kGoalNode], ends.every_source);
  for (std::size_t v = 0, k = 0; v < n; ++v) {
    if (v != kGoalNode) instance->costs[v * n + kGoalNode] = to_goal[k++] + entering_[kGoalNode];
  }
  const Landmarks landmarks = landmarkCosts(ends);
  parallelFor(n, [&](std::size_t v) {
    if (v != kGoalNode) fillRow(ends, landmarks, v, &instance->costs[v * n]);
  });
  for (std::size_t v = 0; v < n; ++v) {
    for (std::size_t w = 1; w < n; ++w) {
      if (v != kGoalNode && w != v && exact(static_cast<int>(v), static_cast<int>(w))) {
        ++exact_count_;
      }
    }
  }
}

LazyTransitionCosts::RouteEnds LazyTransitionCosts::locateEnds() const {
  const std::size_t n = sources_.size();
  RouteEnds ends;
  std::vector<Point2> points;
  ends.source_index.assign(n, 0);
  ends.target_index.assign(n, 0);
  for (std::size_t v = 0; v < n; ++v) {
    if (v == kGoalNode) continue;
    ends.source_index[v] = points.size();
    ends.every_source.push_back(points.size());
    points.push_back(sources_[v]);
  }
  for (std::size_t v = 0; v < n; ++v) {
    if (v == kStartNode) continue;
    ends.target_index[v] = points.size();
    points.push_back(targets_[v]);
  }
  ends.located = graph_.locateAll(points);
  return ends;
}

LazyTransitionCosts::Landmarks LazyTransitionCosts::landmarkCosts(const RouteEnds& ends) const {
  const std::size_t n = sources_.size();
  const std::vector<std::size_t> landmarks = chooseLandmarks(ends.every_source);
  std::vector<std::size_t> every_point(ends.located.size());
  std::iota(every_point.begin(), every_point.end(), 0);
  Landmarks result;
  result.from_landmark.resize(landmarks.size());
  result.to_target.resize(landmarks.size());
  parallelFor(landmarks.size(), [&](std::size_t k) {
    const std::vector<double> costs = graph_.costsFrom(ends.located, landmarks[k], every_point);
    result.from_landmark[k].assign(n, kUnknown);
    result.to_target[k] = Eigen::ArrayXd::Constant(static_cast<Eigen::Index>(n), kUnknown);
    for (std::size_t v = 0; v < n; ++v) {
      if (v != kGoalNode) result.from_landmark[k][v] = costs[ends.source_index[v]];
      if (v != kStartNode) result.to_target[k][v] = costs[ends.target_index[v]] + entering_[v];
    }
  });
  return result;
}

void LazyTransitionCosts::fillRow(const RouteEnds& ends, const Landmarks& landmarks, std::size_t v,
                                  double* row_costs) const {
  const std::size_t n = sources_.size();
  Eigen::Map<Eigen::ArrayXd> row(row_costs, static_cast<Eigen::Index>(n));
  const double goal_cost = row[kGoalNode];
  row = kUnknown;
  for (std::size_t k = 0; k < landmarks.to_target.size(); ++k) {
    row = row.min(landmarks.to_target[k] + landmarks.from_landmark[k][v]);
  }
  row[kStartNode] = 0.0;
  row[kGoalNode] = goal_cost;
  row[v] = 0.0;
  const std::size_t from_cluster = static_cast<std::size_t>(cluster_of_[v]);
  std::vector<std::size_t> routed;
  std::vector<std::size_t> routed_targets;
  for (std::size_t w = 2; w < n; ++w) {
    if (w == v) continue;
    if (candidate_[from_cluster * cluster_count_ + static_cast<std::size_t>(cluster_of_[w])]) {
      routed.push_back(w);
      routed_targets.push_back(ends.target_index[w]);
    } else if (!std::isfinite(row[w])) {
      row[w] = segment_cost_.of(sources_[v], targets_[w]) + entering_[w];
    }
  }
  const std::vector<double> routes =
      graph_.costsFrom(ends.located, ends.source_index[v], routed_targets);
  for (std::size_t k = 0; k < routed.size(); ++k) {
    row[routed[k]] = routes[k] + entering_[routed[k]];
  }
}

std::vector<std::size_t> LazyTransitionCosts::chooseLandmarks(
    const std::vector<std::size_t>& every_source) const {
  // Farthest-point sampling over the sources (located points every_source[k] = node v's
  // source, v skipping the goal), from the start.
  std::vector<Point2> candidates;
  for (std::size_t v = 0; v < sources_.size(); ++v) {
    if (v != kGoalNode) candidates.push_back(sources_[v]);
  }
  std::vector<std::size_t> chosen = {0};
  std::vector<double> nearest(candidates.size(), kUnknown);
  while (chosen.size() < std::min<std::size_t>(kLandmarks, candidates.size())) {
    const Point2& last = candidates[chosen.back()];
    std::size_t farthest = 0;
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      nearest[k] = std::min(nearest[k], (candidates[k] - last).squaredNorm());
      if (nearest[k] > nearest[farthest]) farthest = k;
    }
    if (nearest[farthest] == 0.0) break;
    chosen.push_back(farthest);
  }
  std::vector<std::size_t> landmarks;
  for (std::size_t k : chosen) landmarks.push_back(every_source[k]);
  return landmarks;
}

void LazyTransitionCosts::chooseCandidates(const std::vector<std::vector<int>>& clusters) {
  const std::size_t m = clusters.size();
  std::vector<Eigen::AlignedBox2d> boxes(m);
  for (std::size_t c = 2; c < m; ++c) {
    for (int v : clusters[c]) {
      boxes[c].extend(sources_[v]);
      boxes[c].extend(targets_[v]);
    }
  }
  cluster_count_ = m;
  candidate_.assign(m * m, 0);
  for (std::size_t c = 0; c < m; ++c) {
    candidate_[kStartCluster * m + c] = 1;
    candidate_[c * m + kGoalCluster] = 1;
  }
  std::vector<std::pair<double, std::size_t>> nearest;
  for (std::size_t c = 2; c < m; ++c) {
    nearest.clear();
    for (std::size_t d = 2; d < m; ++d) {
      if (d != c) nearest.emplace_back(boxes[c].exteriorDistance(boxes[d]), d);
    }
    const std::size_t keep = std::min<std::size_t>(kCandidateCells, nearest.size());
    std::nth_element(nearest.begin(), nearest.begin() + keep, nearest.end());
    for (std::size_t k = 0; k < keep; ++k) {
      candidate_[c * m + nearest[k].second] = 1;
      candidate_[nearest[k].second * m + c] = 1;
    }
  }
}

bool LazyTransitionCosts::exact(int u, int v) const {
  return candidate_[static_cast<std::size_t>(cluster_of_[u]) * cluster_count_ +
                    static_cast<std::size_t>(cluster_of_[v])] ||
         priced_.count(key(u, v)) > 0;
}

bool LazyTransitionCosts::priceEdges(const std::vector<int>& sequence, GtspInstance* instance,
                                     std::vector<char>* changed_clusters) {
  const std::size_t n = static_cast<std::size_t>(instance->node_count);
  bool changed = false;
  for (std::size_t i = 0; i + 1 < sequence.size(); ++i) {
    const int u = sequence[i];
    const int v = sequence[i + 1];
    if (exact(u, v)) continue;
    priced_.insert(key(u, v));
    ++exact_count_;
    const double price = graph_.cost(sources_[u], targets_[v]) + entering_[v];
    double& entry = instance->costs[static_cast<std::size_t>(u) * n + static_cast<std::size_t>(v)];
    if (price != entry) {
      entry = price;
      (*changed_clusters)[cluster_of_[u]] = 1;
      (*changed_clusters)[cluster_of_[v]] = 1;
      changed = true;
    }
  }
  return changed;
}

GtspSolution LazyTransitionCosts::makeExact(GtspInstance* instance, GtspSolution solution,
                                            std::chrono::steady_clock::time_point deadline) {
  GtspLocalSearch search(*instance, -1, kLocalSearchNeighbours);
  std::vector<char> changed(instance->clusters.size(), 0);
  while (priceEdges(solution.nodes, instance, &changed)) {
    search.improve(solution.nodes, deadline, &changed);
    std::fill(changed.begin(), changed.end(), 0);
  }
  solution.cost = gtspTourCost(*instance, solution.nodes);
  return solution;
}

}  // namespace kinematic_coverage::core
