#include "polygon_coverage_ros_bridge/geometry/boundary_simplification.h"

#include <algorithm>
#include <cmath>
#include <queue>
#include <string>
#include <tuple>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/edge_grid.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// A vertex within this distance (relative to the area's size) of the triangle a cut
/// would remove blocks the cut: touching rings and pinch points keep their vertices.
constexpr double kRelativeContactTolerance = 1e-9;

/// One ring while it is simplified: its vertices with the area on their left (the hull
/// counter-clockwise, holes clockwise), linked around the ring; removed vertices are dead.
struct RingState {
  std::vector<Point2> points;
  bool reversed = false;     ///< the given ring ran the other way
  std::size_t first_id = 0;  ///< id of points[0] among the vertices of all rings
  std::vector<int> previous;
  std::vector<int> next;
  std::vector<char> alive;
  std::vector<unsigned> version;  ///< bumped whenever a neighbour changes
  std::size_t alive_count = 0;
};

/// A vertex that may be cut, with the largest distance of the vertices its cut (and the
/// cuts before it between the same neighbours) would leave from the new edge.
struct Candidate {
  double deviation;
  int ring;
  int vertex;
  unsigned version;
  bool operator>(const Candidate& other) const {
    return std::tie(deviation, ring, vertex) > std::tie(other.deviation, other.ring, other.vertex);
  }
};

class Simplifier {
 public:
  Simplifier(const PolygonWithHoles& area, double tolerance);
  PolygonWithHoles run();

 private:
  void consider(int ring, int vertex);
  /// The largest distance from the new edge previous-next of the vertices between them.
  double deviation(const RingState& ring, int vertex) const;
  /// True when no vertex but the three lies in or near the triangle the cut removes.
  bool triangleEmpty(const RingState& ring, int vertex) const;

  double tolerance_;
  double contact_tolerance_ = 0.0;
  std::vector<RingState> rings_;
  std::vector<Point2> all_points_;
  std::vector<std::pair<int, int>> owner_;  ///< (ring, vertex) of each id
  EdgeGrid grid_;
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> queue_;
};

Simplifier::Simplifier(const PolygonWithHoles& area, double tolerance) : tolerance_(tolerance) {
  std::vector<const Ring*> given = {&area.hull};
  for (const Ring& hole : area.holes) given.push_back(&hole);
  double scale = 1.0;
  for (std::size_t r = 0; r < given.size(); ++r) {
    RingState state;
    state.points = *given[r];
    const bool counter_clockwise = signedArea(state.points) > 0.0;
    state.reversed = counter_clockwise != (r == 0);
    if (state.reversed) std::reverse(state.points.begin(), state.points.end());
    const int n = static_cast<int>(state.points.size());
    state.first_id = all_points_.size();
    for (int i = 0; i < n; ++i) {
      state.previous.push_back((i + n - 1) % n);
      state.next.push_back((i + 1) % n);
      all_points_.push_back(state.points[i]);
      owner_.emplace_back(static_cast<int>(r), i);
      scale = std::max(scale, state.points[i].cwiseAbs().maxCoeff());
    }
    state.alive.assign(n, 1);
    state.version.assign(n, 0);
    state.alive_count = static_cast<std::size_t>(n);
    rings_.push_back(std::move(state));
  }
  contact_tolerance_ = kRelativeContactTolerance * scale;
  EdgeGrid::Layout layout;
  layout.cells_per_edge = 1.0;
  layout.padding = contact_tolerance_;
  grid_ = EdgeGrid(all_points_, all_points_, layout);
}

double Simplifier::deviation(const RingState& ring, int vertex) const {
  const int n = static_cast<int>(ring.points.size());
  const Point2& from = ring.points[ring.previous[vertex]];
  const Point2& to = ring.points[ring.next[vertex]];
  double largest = 0.0;
  for (int k = (ring.previous[vertex] + 1) % n; k != ring.next[vertex]; k = (k + 1) % n) {
    largest = std::max(largest, distanceToSegment(ring.points[k], from, to));
  }
  return largest;
}

bool Simplifier::triangleEmpty(const RingState& ring, int vertex) const {
  const Point2& a = ring.points[ring.previous[vertex]];
  const Point2& b = ring.points[vertex];
  const Point2& c = ring.points[ring.next[vertex]];
  const Point2 low = a.cwiseMin(b).cwiseMin(c) - Point2::Constant(contact_tolerance_);
  const Point2 high = a.cwiseMax(b).cwiseMax(c) + Point2::Constant(contact_tolerance_);
  std::vector<int> ids;
  grid_.collect(grid_.cellsOf(low, high), &ids);
  // Signed distance of q from the line through an edge of the triangle (counter-clockwise:
  // the cut vertex turns left), positive inside.
  const auto inside = [&](const Point2& from, const Point2& to, const Point2& q) {
    const double length = (to - from).norm();
    return length == 0.0 || cross(from, to, q) / length >= -contact_tolerance_;
  };
  const auto idOf = [&](int k) { return static_cast<int>(ring.first_id) + k; };
  for (const int id : ids) {
    if (id == idOf(vertex) || id == idOf(ring.previous[vertex]) || id == idOf(ring.next[vertex])) {
      continue;
    }
    const auto [other_ring, other_vertex] = owner_[static_cast<std::size_t>(id)];
    if (!rings_[static_cast<std::size_t>(other_ring)].alive[other_vertex]) continue;
    const Point2& q = all_points_[static_cast<std::size_t>(id)];
    if (inside(a, b, q) && inside(b, c, q) && inside(c, a, q)) return false;
  }
  return true;
}

void Simplifier::consider(int ring_index, int vertex) {
  const RingState& ring = rings_[static_cast<std::size_t>(ring_index)];
  if (!ring.alive[vertex] || ring.alive_count <= 3) return;
  const Point2& a = ring.points[ring.previous[vertex]];
  const Point2& b = ring.points[vertex];
  const Point2& c = ring.points[ring.next[vertex]];
  // Only a vertex where the area turns left (or goes straight) is cut: the cut then takes
  // the triangle from the area instead of adding it.
  if (cross(a, b, c) < 0.0) return;
  const double d = deviation(ring, vertex);
  if (d > tolerance_) return;
  queue_.push({d, ring_index, vertex, ring.version[vertex]});
}

PolygonWithHoles Simplifier::run() {
  for (std::size_t r = 0; r < rings_.size(); ++r) {
    for (std::size_t i = 0; i < rings_[r].points.size(); ++i) {
      consider(static_cast<int>(r), static_cast<int>(i));
    }
  }
  while (!queue_.empty()) {
    const Candidate candidate = queue_.top();
    queue_.pop();
    RingState& ring = rings_[static_cast<std::size_t>(candidate.ring)];
    const int v = candidate.vertex;
    if (!ring.alive[v] || ring.version[v] != candidate.version || ring.alive_count <= 3) continue;
    if (!triangleEmpty(ring, v)) continue;
    const int before = ring.previous[v];
    const int after = ring.next[v];
    ring.alive[v] = 0;
    --ring.alive_count;
    ring.next[before] = after;
    ring.previous[after] = before;
    ++ring.version[before];
    ++ring.version[after];
    consider(candidate.ring, before);
    consider(candidate.ring, after);
  }

  PolygonWithHoles result;
  for (std::size_t r = 0; r < rings_.size(); ++r) {
    const RingState& ring = rings_[r];
    Ring kept;
    for (std::size_t i = 0; i < ring.points.size(); ++i) {
      if (ring.alive[i]) kept.push_back(ring.points[i]);
    }
    if (ring.reversed) std::reverse(kept.begin(), kept.end());
    if (r == 0) {
      result.hull = std::move(kept);
    } else {
      result.holes.push_back(std::move(kept));
    }
  }
  return result;
}

}  // namespace

BoundarySimplification::BoundarySimplification(double tolerance) : tolerance_(tolerance) {
  if (!std::isfinite(tolerance) || tolerance < 0.0) {
    throw InvalidInputError("boundary simplification: tolerance " + std::to_string(tolerance) +
                            " m must be finite and >= 0");
  }
}

PolygonWithHoles BoundarySimplification::simplify(const PolygonWithHoles& area) const {
  if (area.hull.size() < 3) return area;
  return Simplifier(area, tolerance_).run();
}

std::size_t BoundarySimplification::vertexCount(const PolygonWithHoles& area) {
  std::size_t count = area.hull.size();
  for (const Ring& hole : area.holes) count += hole.size();
  return count;
}

}  // namespace kinematic_coverage::core
