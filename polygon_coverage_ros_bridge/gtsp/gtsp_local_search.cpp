#include "polygon_coverage_ros_bridge/gtsp/gtsp_local_search.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace kinematic_coverage::core {
namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
/// Improvements smaller than this fraction of the largest edge cost are ignored, so that
/// rounding noise never cycles the search.
constexpr double kRelativeImprovementEpsilon = 1e-12;
}  // namespace

GtspLocalSearch::GtspLocalSearch(const GtspInstance& instance, int anchor_cluster,
                                 int neighbour_count)
    : instance_(instance),
      cycle_(!instance.isPath()),
      anchor_cluster_(anchor_cluster),
      reverse_nodes_(instance.reverse_nodes),
      optimizer_(instance) {
  const int m = static_cast<int>(instance.clusters.size());
  cluster_of_.assign(static_cast<std::size_t>(instance.node_count), -1);
  for (int c = 0; c < m; ++c) {
    for (int node : instance.clusters[c]) cluster_of_[node] = c;
  }
  double max_cost = 0.0;
  for (double c : instance.costs) max_cost = std::max(max_cost, c);
  epsilon_ = std::max(max_cost, 1.0) * kRelativeImprovementEpsilon;
  // Cluster distance: the cheapest edge in either direction between their nodes.
  std::vector<double> distance(static_cast<std::size_t>(m) * m, kInfinity);
  for (int u = 0; u < instance.node_count; ++u) {
    for (int v = 0; v < instance.node_count; ++v) {
      const int cu = cluster_of_[u];
      const int cv = cluster_of_[v];
      if (cu == cv) continue;
      const double d = std::min(instance.cost(u, v), instance.cost(v, u));
      double& entry = distance[static_cast<std::size_t>(cu) * m + cv];
      entry = std::min(entry, d);
    }
  }
  neighbours_.resize(m);
  std::vector<int> order;
  for (int c = 0; c < m; ++c) {
    order.resize(m);
    std::iota(order.begin(), order.end(), 0);
    order.erase(order.begin() + c);
    const std::size_t keep = std::min<std::size_t>(order.size(), neighbour_count);
    std::partial_sort(order.begin(), order.begin() + keep, order.end(), [&](int a, int b) {
      const double da = distance[static_cast<std::size_t>(c) * m + a];
      const double db = distance[static_cast<std::size_t>(c) * m + b];
      return da < db || (da == db && a < b);
    });
    neighbours_[c].assign(order.begin(), order.begin() + keep);
  }
  cluster_distance_ = std::make_shared<const std::vector<double>>(std::move(distance));
  position_.assign(m, -1);
}

double GtspLocalSearch::sequenceCost(const std::vector<int>& sequence) const {
  double total = 0.0;
  for (std::size_t i = 0; i + 1 < sequence.size(); ++i) total += cost(sequence[i], sequence[i + 1]);
  return total;
}

double GtspLocalSearch::optimizeClusters(std::vector<int>& sequence) {
  const std::size_t length = sequence.size();
  if (cycle_) {
    clusters_buffer_.resize(length - 1);
    for (std::size_t i = 0; i + 1 < length; ++i) clusters_buffer_[i] = cluster_of_[sequence[i]];
    optimizer_.optimizeCycle(clusters_buffer_, nodes_buffer_);
    std::copy(nodes_buffer_.begin(), nodes_buffer_.end(), sequence.begin());
    sequence.back() = sequence.front();
  } else {
    clusters_buffer_.resize(length);
    for (std::size_t i = 0; i < length; ++i) clusters_buffer_[i] = cluster_of_[sequence[i]];
    optimizer_.optimizePath(clusters_buffer_, nodes_buffer_);
    sequence = nodes_buffer_;
  }
  return sequenceCost(sequence);
}

void GtspLocalSearch::index(const std::vector<int>& sequence) {
  const std::size_t length = sequence.size();
  for (std::size_t i = 0; i < length; ++i)
    position_[cluster_of_[sequence[i]]] = static_cast<int>(i);
  if (cycle_) position_[anchor_cluster_] = 0;
  edge_cost_.resize(length);
  forward_prefix_.assign(length, 0.0);
  backward_prefix_.assign(length, 0.0);
  for (std::size_t i = 0; i + 1 < length; ++i) {
    edge_cost_[i] = cost(sequence[i], sequence[i + 1]);
    forward_prefix_[i + 1] = forward_prefix_[i] + edge_cost_[i];
    backward_prefix_[i + 1] =
        backward_prefix_[i] + cost(reverse(sequence[i + 1]), reverse(sequence[i]));
  }
}

void GtspLocalSearch::touch(int node) {
  for (std::vector<char>& look : look_) look[cluster_of_[node]] = 1;
}

void GtspLocalSearch::touchRange(const std::vector<int>& sequence, std::ptrdiff_t first,
                                 std::ptrdiff_t last) {
  const std::ptrdiff_t size = static_cast<std::ptrdiff_t>(sequence.size());
  for (std::ptrdiff_t i = std::max<std::ptrdiff_t>(first, 0); i <= last && i < size; ++i) {
    touch(sequence[i]);
  }
}

template <typename Visit>
void GtspLocalSearch::forEachPosition(int c, std::size_t length, Visit visit) const {
  visit(static_cast<std::size_t>(position_[c]));
  if (cycle_ && c == anchor_cluster_) visit(length - 1);
}

bool GtspLocalSearch::reinsertPass(std::vector<int>& sequence) {
  bool improved = false;
  const std::size_t length = sequence.size();
  const std::size_t clusters = instance_.clusters.size();
  edge_stamp_.resize(length, 0);
  for (std::size_t i = 1; i + 1 < length; ++i) {
    const int v = sequence[i];
    const int a = sequence[i - 1];
    const int b = sequence[i + 1];
    const int c = cluster_of_[v];
    if (!look_[kReinsert][c]) continue;
    const std::vector<int>& members = instance_.clusters[c];
    const double gain = cost(a, v) + cost(v, b) - cost(a, b);
    double best = gain - epsilon_;
    std::size_t best_edge = length;  // edge (p, p+1) of the current sequence; i-1 = (a, b)
    int best_node = -1;
    ++stamp_;
    const double* to_cluster = &(*cluster_distance_)[static_cast<std::size_t>(c) * clusters];
    auto tryEdge = [&](std::size_t p, int x, int y, double base) {
      if (edge_stamp_[p] == stamp_) return;  // already tried from another neighbour
      edge_stamp_[p] = stamp_;
      // No member can do better than the cluster distances allow (each sum and difference
      // of them rounds to at most the members' own, so nothing that could win is skipped).
      if (to_cluster[cluster_of_[x]] + to_cluster[cluster_of_[y]] - base >= best) return;
      for (int u : members) {
        const double added = cost(x, u) + cost(u, y) - base;
        if (added < best) {
          best = added;
          best_edge = p;
          best_node = u;
        }
      }
    };
    tryEdge(i - 1, a, b, cost(a, b));
    for (int near : neighbours_[c]) {
      forEachPosition(near, length, [&](std::size_t q) {
        if (q >= 1 && q - 1 != i - 1 && q - 1 != i) {
          tryEdge(q - 1, sequence[q - 1], sequence[q], edge_cost_[q - 1]);
        }
        if (q + 1 < length && q != i - 1 && q != i) {
          tryEdge(q, sequence[q], sequence[q + 1], edge_cost_[q]);
        }
      });
    }
    if (best_node < 0) {
      look_[kReinsert][c] = 0;
      continue;
    }
    touch(a);
    touch(b);
    sequence.erase(sequence.begin() + static_cast<std::ptrdiff_t>(i));
    std::size_t insert_after = best_edge;
    if (best_edge > i) --insert_after;
    sequence.insert(sequence.begin() + static_cast<std::ptrdiff_t>(insert_after + 1), best_node);
    touchRange(sequence, static_cast<std::ptrdiff_t>(insert_after),
               static_cast<std::ptrdiff_t>(insert_after) + 2);
    index(sequence);
    improved = true;
  }
  return improved;
}

bool GtspLocalSearch::orOptPass(std::vector<int>& sequence) {
  bool improved = false;
  const std::size_t length = sequence.size();
  for (std::size_t segment = 2; segment <= 3; ++segment) {
    for (std::size_t i = 1; i + segment < length; ++i) {
      const std::size_t j = i + segment - 1;
      const int first = sequence[i];
      const int last = sequence[j];
      if (!look_[kOrOpt][cluster_of_[first]] && !look_[kOrOpt][cluster_of_[last]]) continue;
      const int before = sequence[i - 1];
      const int after = sequence[j + 1];
      const double gain = cost(before, first) + cost(last, after) - cost(before, after);
      const double reversal =
          (backward_prefix_[j] - backward_prefix_[i]) - (forward_prefix_[j] - forward_prefix_[i]);
      double best = gain - epsilon_;
      std::size_t best_edge = length;
      bool best_reversed = false;
      auto tryEdge = [&](std::size_t p) {
        if (p + 1 >= length || (p + 1 >= i && p <= j)) return;
        const int x = sequence[p];
        const int y = sequence[p + 1];
        const double base = edge_cost_[p];
        const double forward = cost(x, first) + cost(last, y) - base;
        const double backward = cost(x, reverse(last)) + cost(reverse(first), y) - base + reversal;
        if (forward < best) {
          best = forward;
          best_edge = p;
          best_reversed = false;
        }
        if (backward < best) {
          best = backward;
          best_edge = p;
          best_reversed = true;
        }
      };
      for (int end : {first, last}) {
        for (int near : neighbours_[cluster_of_[end]]) {
          forEachPosition(near, length, [&](std::size_t q) {
            if (q >= 1) tryEdge(q - 1);
            tryEdge(q);
          });
        }
      }
      if (best_edge == length) {
        look_[kOrOpt][cluster_of_[first]] = 0;
        continue;
      }
      touch(before);
      touch(after);
      scratch_.assign(sequence.begin() + static_cast<std::ptrdiff_t>(i),
                      sequence.begin() + static_cast<std::ptrdiff_t>(j + 1));
      if (best_reversed) {
        std::reverse(scratch_.begin(), scratch_.end());
        for (int& node : scratch_) node = reverse(node);
      }
      sequence.erase(sequence.begin() + static_cast<std::ptrdiff_t>(i),
                     sequence.begin() + static_cast<std::ptrdiff_t>(j + 1));
      std::size_t insert_after = best_edge;
      if (best_edge > j) insert_after -= segment;
      sequence.insert(sequence.begin() + static_cast<std::ptrdiff_t>(insert_after + 1),
                      scratch_.begin(), scratch_.end());
      touchRange(sequence, static_cast<std::ptrdiff_t>(insert_after),
                 static_cast<std::ptrdiff_t>(insert_after + segment) + 1);
      index(sequence);
      improved = true;
    }
  }
  return improved;
}

bool GtspLocalSearch::twoOptPass(std::vector<int>& sequence) {
  bool improved = false;
  const std::size_t length = sequence.size();
  // Removes edges (a, a+1) and (b, b+1), reversing a+1..b (with reverse nodes).
  auto tryMove = [&](std::size_t a, std::size_t b) {
    if (b < a + 2 || b + 2 > length) return false;
    const double delta = cost(sequence[a], reverse(sequence[b])) +
                         cost(reverse(sequence[a + 1]), sequence[b + 1]) - edge_cost_[a] -
                         edge_cost_[b] + (backward_prefix_[b] - backward_prefix_[a + 1]) -
                         (forward_prefix_[b] - forward_prefix_[a + 1]);
    if (delta >= -epsilon_) return false;
    std::reverse(sequence.begin() + static_cast<std::ptrdiff_t>(a + 1),
                 sequence.begin() + static_cast<std::ptrdiff_t>(b + 1));
    for (std::size_t k = a + 1; k <= b; ++k) sequence[k] = reverse(sequence[k]);
    touchRange(sequence, static_cast<std::ptrdiff_t>(a), static_cast<std::ptrdiff_t>(b) + 1);
    index(sequence);
    return true;
  };
  for (std::size_t a = 0; a + 3 <= length; ++a) {
    if (!look_[kTwoOpt][cluster_of_[sequence[a]]] &&
        !look_[kTwoOpt][cluster_of_[sequence[a + 1]]]) {
      continue;
    }
    bool moved = false;
    for (int near : neighbours_[cluster_of_[sequence[a]]]) {
      forEachPosition(near, length, [&](std::size_t q) {
        if (!moved && q > a) moved = tryMove(a, q);
      });
      if (moved) break;
    }
    if (!moved) {
      for (int near : neighbours_[cluster_of_[sequence[a + 1]]]) {
        forEachPosition(near, length, [&](std::size_t q) {
          if (!moved && q > a + 1) moved = tryMove(a, q - 1);
        });
        if (moved) break;
      }
    }
    if (!moved) look_[kTwoOpt][cluster_of_[sequence[a]]] = 0;
    improved = improved || moved;
  }
  return improved;
}

void GtspLocalSearch::touchChanged(const std::vector<int>& sequence) {
  for (std::size_t i = 0; i < sequence.size(); ++i) {
    if (sequence[i] != previous_[i]) {
      touchRange(sequence, static_cast<std::ptrdiff_t>(i) - 1, static_cast<std::ptrdiff_t>(i) + 1);
    }
  }
}

double GtspLocalSearch::improve(std::vector<int>& sequence, Clock::time_point deadline,
                                const std::vector<char>* focus) {
  previous_ = sequence;
  double current = optimizeClusters(sequence);
  if (sequence.size() < 3) return current;
  if (focus == nullptr) {
    for (std::vector<char>& look : look_) look.assign(instance_.clusters.size(), 1);
  } else {
    for (std::vector<char>& look : look_) look = *focus;
    touchChanged(sequence);
  }
  while (Clock::now() < deadline) {
    index(sequence);
    bool improved = reinsertPass(sequence);
    improved = orOptPass(sequence) || improved;
    improved = twoOptPass(sequence) || improved;
    // No move: the sequence is the last cluster optimization's, which would return it again.
    if (!improved) break;
    previous_ = sequence;
    const double optimized = optimizeClusters(sequence);
    touchChanged(sequence);
    if (!improved && optimized >= current - epsilon_) {
      current = optimized;
      break;
    }
    current = optimized;
  }
  return current;
}

}  // namespace kinematic_coverage::core
