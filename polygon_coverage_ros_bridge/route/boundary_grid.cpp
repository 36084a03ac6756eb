#include "polygon_coverage_ros_bridge/route/boundary_grid.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// Tolerance as a fraction of the map's extent (the brief's ~1e-9 relative).
constexpr double kRelativeTolerance = 1e-9;
/// Grid cells per edge, and the most cells along one axis.
constexpr double kCellsPerEdge = 2.0;
constexpr int kMaxCellsPerAxis = 512;

double crossOf(const Point2& u, const Point2& v) { return u.x() * v.y() - u.y() * v.x(); }

/// The largest angle by which a straight piece of the given length, leaving a point on a
/// ray, may turn off the ray and stay within `tolerance` of it: length * sin(angle).
double angleWithin(double tolerance, double length) {
  return std::asin(std::min(1.0, tolerance / length));
}

/// True when every vertex of the ring lies within `tolerance` of its first.
bool collapses(const Ring& ring, double tolerance) {
  return std::all_of(ring.begin(), ring.end(), [&](const Point2& p) {
    return p.allFinite() && (p - ring.front()).norm() <= tolerance;
  });
}

/// The ring without repeated consecutive vertices, validated and oriented.
Ring cleanedRing(const Ring& ring, const std::string& name, bool counter_clockwise,
                 double tolerance) {
  Ring result;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (!ring[i].allFinite()) {
      throw InvalidInputError(name + " vertex " + std::to_string(i) +
                              " has a non-finite coordinate");
    }
    if (result.empty() || (ring[i] - result.back()).norm() > tolerance) result.push_back(ring[i]);
  }
  while (result.size() > 1 && (result.front() - result.back()).norm() <= tolerance) {
    result.pop_back();
  }
  const double signed_area = result.size() < 3 ? 0.0 : signedArea(result);
  if (result.size() < 3 || signed_area == 0.0) {
    throw InvalidInputError(name + " has fewer than 3 distinct vertices or zero area");
  }
  if ((signed_area > 0.0) != counter_clockwise) std::reverse(result.begin(), result.end());
  return result;
}

}  // namespace

BoundaryGrid::BoundaryGrid(const PolygonWithHoles& polygon) {
  // Rounding grows with the coordinates' magnitude, not only with the polygon's extent: a
  // small part of the offset free area far from the origin (planner_fuzzer: 0.55 m across at
  // x = 15 m) carries the rounding of the stages before, relative to its coordinates.
  double scale = 1.0;
  if (!polygon.hull.empty()) {
    Eigen::AlignedBox2d box;
    for (const Point2& p : polygon.hull) {
      if (p.allFinite()) box.extend(p);
    }
    if (!box.isEmpty()) {
      scale = std::max({scale, box.sizes().maxCoeff(), box.min().cwiseAbs().maxCoeff(),
                        box.max().cwiseAbs().maxCoeff()});
    }
  }
  tolerance_ = kRelativeTolerance * scale;
  polygon_.hull = cleanedRing(polygon.hull, "hull", true, tolerance_);
  for (std::size_t h = 0; h < polygon.holes.size(); ++h) {
    // A hole whose vertices all lie within the tolerance of each other is a point to every
    // test here (they all allow the tolerance): it blocks nothing.
    if (collapses(polygon.holes[h], tolerance_)) continue;
    polygon_.holes.push_back(
        cleanedRing(polygon.holes[h], "hole " + std::to_string(h), false, tolerance_));
  }
  buildClusters();
  buildGrid();
  addTouchingEdges();
}

void BoundaryGrid::buildClusters() {
  // Every ring vertex and its edge to the next vertex; the free area lies to the left.
  std::vector<Point2> vertices;
  std::vector<int> next;
  std::vector<int> previous;
  auto addRing = [&](const Ring& ring, int ring_index) {
    const int first = static_cast<int>(vertices.size());
    const int n = static_cast<int>(ring.size());
    for (int i = 0; i < n; ++i) {
      vertices.push_back(ring[i]);
      next.push_back(first + (i + 1) % n);
      previous.push_back(first + (i + n - 1) % n);
      edge_ring_.push_back(ring_index);
    }
  };
  addRing(polygon_.hull, 0);
  for (std::size_t h = 0; h < polygon_.holes.size(); ++h) {
    addRing(polygon_.holes[h], static_cast<int>(h) + 1);
  }

  // Cluster coinciding vertices (pinch points): sweep in x, join within tolerance.
  const int count = static_cast<int>(vertices.size());
  std::vector<int> order(count);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return vertices[a].x() < vertices[b].x(); });
  std::vector<int> cluster_of(count, -1);
  for (int i = 0; i < count; ++i) {
    const int v = order[i];
    if (cluster_of[v] >= 0) continue;
    cluster_of[v] = static_cast<int>(clusters_.size());
    clusters_.push_back({vertices[v], {}, {}, false});
    for (int j = i + 1; j < count && vertices[order[j]].x() - vertices[v].x() <= tolerance_; ++j) {
      if (cluster_of[order[j]] < 0 && (vertices[order[j]] - vertices[v]).norm() <= tolerance_) {
        cluster_of[order[j]] = cluster_of[v];
      }
    }
  }
  for (int v = 0; v < count; ++v) {
    edge_start_.push_back(vertices[v]);
    edge_end_.push_back(vertices[next[v]]);
    start_cluster_.push_back(cluster_of[v]);
    end_cluster_.push_back(cluster_of[next[v]]);
  }

  // Rays of the corners: the outgoing edge has the free area counter-clockwise of it,
  // the incoming edge (seen from the vertex) clockwise of it.
  std::vector<int> corners(clusters_.size(), 0);
  for (int v = 0; v < count; ++v) {
    Cluster& cluster = clusters_[cluster_of[v]];
    const Point2& here = vertices[v];
    const Point2 to_next = vertices[next[v]] - here;
    const Point2 to_previous = vertices[previous[v]] - here;
    cluster.ray_angles.push_back(std::atan2(to_next.y(), to_next.x()));
    cluster.ray_outgoing.push_back(1);
    cluster.ray_angles.push_back(std::atan2(to_previous.y(), to_previous.x()));
    cluster.ray_outgoing.push_back(0);
    // Reflex for the free area: a right turn by more than the tolerance.
    const double chord = (vertices[next[v]] - vertices[previous[v]]).norm();
    const double turn = crossOf(-to_previous, to_next);
    if (turn < 0.0 && -turn > tolerance_ * chord) cluster.bend = true;
    ++corners[cluster_of[v]];
  }
  for (std::size_t k = 0; k < clusters_.size(); ++k) {
    if (corners[k] > 1) clusters_[k].bend = true;
  }
}

void BoundaryGrid::buildGrid() {
  // Each edge is registered in every cell its box, grown by the tolerance, overlaps.
  EdgeGrid::Layout layout;
  layout.cells_per_edge = kCellsPerEdge;
  layout.max_cells_per_axis = kMaxCellsPerAxis;
  layout.margin = 2.0 * tolerance_;
  layout.padding = tolerance_;
  grid_ = EdgeGrid(edge_start_, edge_end_, layout);
}

void BoundaryGrid::addTouchingEdges() {
  // A vertex lying on another edge's interior (a ring touching an edge): that edge's two
  // rays join the vertex's cluster, which becomes a possible bend.
  for (int k = 0; k < static_cast<int>(clusters_.size()); ++k) {
    Cluster& cluster = clusters_[k];
    const Point2 p = cluster.position;
    const int column = grid_.column(p.x());
    const int row = grid_.row(p.y());
    for (const int* edge = grid_.cellBegin(column, row); edge != grid_.cellEnd(column, row);
         ++edge) {
      const int e = *edge;
      if (k == start_cluster_[e] || k == end_cluster_[e]) continue;
      if (distanceToSegment(p, edge_start_[e], edge_end_[e]) > tolerance_) continue;
      const Point2 forward = edge_end_[e] - p;
      const Point2 backward = edge_start_[e] - p;
      cluster.ray_angles.push_back(std::atan2(forward.y(), forward.x()));
      cluster.ray_outgoing.push_back(1);
      cluster.ray_angles.push_back(std::atan2(backward.y(), backward.x()));
      cluster.ray_outgoing.push_back(0);
      cluster.bend = true;
    }
  }
}

bool BoundaryGrid::contains(const Point2& p) const {
  // Beyond the grid, a point is farther than its margin from every edge and outside.
  if (!p.allFinite() || !grid_.covers(p)) return false;
  const int column = grid_.column(p.x());
  const int row = grid_.row(p.y());
  // Every edge within the tolerance of p is registered in p's cell (boxes grown by it).
  for (const int* edge = grid_.cellBegin(column, row); edge != grid_.cellEnd(column, row); ++edge) {
    if (distanceToSegment(p, edge_start_[*edge], edge_end_[*edge]) <= tolerance_) return true;
  }
  // Even-odd crossings of the ray from p to the right, per ring (the test of insideRing).
  // An edge crossing the ray at x is registered in the cell of x in p's row, so it is
  // counted there, and only there, however many cells it spans.
  bool inside_hull = false;
  std::vector<int> crossed_holes;
  for (int c = column; c < grid_.columns(); ++c) {
    for (const int* edge = grid_.cellBegin(c, row); edge != grid_.cellEnd(c, row); ++edge) {
      const Point2& a = edge_end_[*edge];
      const Point2& b = edge_start_[*edge];
      if ((a.y() > p.y()) == (b.y() > p.y())) continue;
      const double x_cross = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() >= x_cross || grid_.column(x_cross) != c) continue;
      if (edge_ring_[*edge] == 0) {
        inside_hull = !inside_hull;
      } else {
        crossed_holes.push_back(edge_ring_[*edge]);
      }
    }
  }
  if (!inside_hull) return false;
  // Inside a hole: crossed an odd number of times.
  std::sort(crossed_holes.begin(), crossed_holes.end());
  for (std::size_t i = 0; i < crossed_holes.size();) {
    std::size_t j = i;
    while (j < crossed_holes.size() && crossed_holes[j] == crossed_holes[i]) ++j;
    if ((j - i) % 2 == 1) return false;
    i = j;
  }
  return true;
}

BoundaryGrid::Contact BoundaryGrid::contactOf(const Point2& p) const {
  Contact contact;
  if (!p.allFinite()) return contact;
  const int column = grid_.column(p.x());
  const int row = grid_.row(p.y());
  for (const int* edge = grid_.cellBegin(column, row); edge != grid_.cellEnd(column, row); ++edge) {
    const int e = *edge;
    if ((p - edge_start_[e]).norm() <= tolerance_) return {start_cluster_[e], {}};
    if ((p - edge_end_[e]).norm() <= tolerance_) return {end_cluster_[e], {}};
    if (distanceToSegment(p, edge_start_[e], edge_end_[e]) <= tolerance_) {
      contact.edges.push_back(e);
    }
  }
  // Within the tolerance of two edges that meet at a vertex with wall in the narrow angle
  // between them (a reflex corner, or a pinch), p lies on that wall's sliver, narrower than
  // the tolerance there: the vertex's rays judge its directions, the free side being the
  // union of the edges' free sides there, not the intersection that their half-planes
  // give. In a sliver of free area the intersection is right: the edges alone judge.
  for (std::size_t i = 0; i < contact.edges.size() && contact.cluster < 0; ++i) {
    for (std::size_t j = i + 1; j < contact.edges.size() && contact.cluster < 0; ++j) {
      contact.cluster = wallCornerBetween(contact.edges[i], contact.edges[j]);
    }
  }
  return contact;
}

int BoundaryGrid::wallCornerBetween(int e, int f) const {
  for (int k : {start_cluster_[e], end_cluster_[e]}) {
    if (k != start_cluster_[f] && k != end_cluster_[f]) continue;
    const Point2& corner = clusters_[k].position;
    auto away = [&](int edge) {
      const Point2& far_end = start_cluster_[edge] == k ? edge_end_[edge] : edge_start_[edge];
      return Point2((far_end - corner).normalized());
    };
    const Point2 middle = away(e) + away(f);  // bisects the narrow angle
    if (middle.squaredNorm() > 0.0 && !directionFree(k, middle, 0.0)) return k;
  }
  return -1;
}

bool BoundaryGrid::directionFree(int cluster, const Point2& direction,
                                 double angle_tolerance) const {
  // The ray nearest clockwise of the direction tells the side: free counter-clockwise of
  // an outgoing edge, clockwise of an incoming one. Along a ray is on the boundary.
  const Cluster& c = clusters_[cluster];
  const double angle = std::atan2(direction.y(), direction.x());
  double nearest = 2.0 * M_PI;
  bool free = true;
  for (std::size_t i = 0; i < c.ray_angles.size(); ++i) {
    // Both angles lie in [-pi, pi] (atan2), so one turn brings the difference into
    // [0, 2 pi], as fmod would, without its cost in the visibility test's inner loop.
    double delta = angle - c.ray_angles[i];
    if (delta < 0.0) delta += 2.0 * M_PI;
    if (delta <= angle_tolerance || delta >= 2.0 * M_PI - angle_tolerance) return true;
    if (delta < nearest) {
      nearest = delta;
      free = c.ray_outgoing[i] != 0;
    }
  }
  return free;
}

bool BoundaryGrid::runsIntoCorner(int cluster, const Point2& direction) const {
  const double length = direction.norm();
  return clusters_[cluster].ray_angles.size() == 2 && length > 0.0 &&
         !directionFree(cluster, direction, angleWithin(tolerance_, length));
}

bool BoundaryGrid::passesInsideConvexCorner(int cluster, const Point2& a, const Point2& b) const {
  const Cluster& c = clusters_[cluster];
  if (c.bend || c.ray_angles.size() != 2) return false;
  const int out = c.ray_outgoing[0] != 0 ? 0 : 1;
  const Point2 out_ray(std::cos(c.ray_angles[out]), std::sin(c.ray_angles[out]));
  const Point2 in_ray(std::cos(c.ray_angles[1 - out]), std::sin(c.ray_angles[1 - out]));
  double wedge = std::fmod(c.ray_angles[1 - out] - c.ray_angles[out], 2.0 * M_PI);
  if (wedge < 0.0) wedge += 2.0 * M_PI;
  if (!(wedge < M_PI)) return false;  // the free angle there
  // Both ends within the tolerance of the free wedge (the intersection of the half-planes
  // left of the outgoing ray and right of the incoming one): so is the whole segment, and
  // near the corner the wedge is the area. Judging the segment's own direction from the
  // rays instead fails for a chord nearly along an edge, which passes the corner at about
  // the tolerance (planner_fuzzer).
  for (const Point2& end : {a, b}) {
    const Point2 from_vertex = end - c.position;
    if (crossOf(out_ray, from_vertex) < -tolerance_ || crossOf(in_ray, from_vertex) > tolerance_) {
      return false;
    }
  }
  return true;
}

bool BoundaryGrid::endAllows(const Contact& contact, const Point2& far_end) const {
  if (contact.cluster >= 0) {
    // The end lies up to the tolerance from the vertex, on either side of its edges (a lane
    // end just beyond a convex corner): the segment stays within the tolerance of the one
    // from the vertex itself, so the vertex's rays judge that one's direction, with the
    // angle it may deviate over its own length. A far end as close to the vertex leaves the
    // whole segment within the tolerance of it.
    const Point2 from_vertex = far_end - clusters_[contact.cluster].position;
    const double length = from_vertex.norm();
    if (length <= tolerance_) return true;
    return directionFree(contact.cluster, from_vertex, angleWithin(tolerance_, length));
  }
  for (int e : contact.edges) {
    const Point2 along = edge_end_[e] - edge_start_[e];
    // The far end may lie right of the edge's line by at most the tolerance (measured
    // from the line itself: the end may lie up to the tolerance off it either way).
    if (crossOf(along, far_end - edge_start_[e]) < -tolerance_ * along.norm()) return false;
  }
  return true;
}

bool BoundaryGrid::touches(const Contact& contact, int edge) const {
  if (!contact.edges.empty()) {
    return std::find(contact.edges.begin(), contact.edges.end(), edge) != contact.edges.end();
  }
  return contact.cluster >= 0 &&
         (contact.cluster == start_cluster_[edge] || contact.cluster == end_cluster_[edge]);
}

bool BoundaryGrid::segmentInside(const Point2& a, const Point2& b) const {
  return segmentInside(a, contactOf(a), b, contactOf(b));
}

bool BoundaryGrid::segmentInside(const Point2& a, const Contact& a_contact, const Point2& b,
                                 const Contact& b_contact) const {
  const Point2 d = b - a;
  const double length_sq = d.squaredNorm();
  const double length = std::sqrt(length_sq);
  if (!(length > tolerance_)) return length <= tolerance_;
  if (!endAllows(a_contact, b) || !endAllows(b_contact, a)) return false;
  const double side_tolerance = tolerance_ * length;  // cross products scale with |d|
  return grid_.visitEdgesAlong(a, b, [&](int e) {
    const Point2& s = edge_start_[e];
    const Point2& t = edge_end_[e];
    const double side_s = crossOf(d, s - a);
    const double side_t = crossOf(d, t - a);
    if ((side_s > side_tolerance && side_t > side_tolerance) ||
        (side_s < -side_tolerance && side_t < -side_tolerance)) {
      return true;
    }
    // A vertex on the open segment: the directions from it to both ends must be free
    // there. The vertex lies up to the tolerance off the segment's line, so each part,
    // from the vertex to an end, may deviate from a ray by the tolerance over that part's
    // own length: near an end this angle is large (a boundary end just past a corner sees
    // along the corner's other edge) while the part still strays at most the tolerance
    // from the boundary. Measured from the vertex itself, not along the segment: an end
    // just past a reflex corner, on its edge, lies along that edge's ray from the corner
    // although the segment's direction, passing the corner within the tolerance, does not.
    if (std::abs(side_s) <= side_tolerance) {
      const double along = (s - a).dot(d);
      const double to_a = (s - a).norm();
      const double to_b = (s - b).norm();
      if (along > 0.0 && along < length_sq && to_a > tolerance_ && to_b > tolerance_) {
        const int k = start_cluster_[e];
        if (!passesInsideConvexCorner(k, a, b) &&
            (!directionFree(k, b - s, angleWithin(tolerance_, to_b)) ||
             !directionFree(k, a - s, angleWithin(tolerance_, to_a)))) {
          return false;
        }
      }
    }
    // An edge crossing the segment's line: a proper crossing leaves the area, except
    // through an end, which that end's contact judged.
    const bool straddles = (side_s > side_tolerance && side_t < -side_tolerance) ||
                           (side_s < -side_tolerance && side_t > side_tolerance);
    if (!straddles) return true;
    const double side_a = crossOf(t - s, a - s);
    const double side_b = crossOf(t - s, b - s);
    if (!((side_a > 0.0 && side_b < 0.0) || (side_a < 0.0 && side_b > 0.0))) return true;
    if (touches(a_contact, e) || touches(b_contact, e)) return true;
    return distanceToSegment(a, s, t) <= tolerance_ || distanceToSegment(b, s, t) <= tolerance_;
  });
}

std::vector<int> BoundaryGrid::bendClusters() const {
  std::vector<int> result;
  for (std::size_t k = 0; k < clusters_.size(); ++k) {
    if (clusters_[k].bend) result.push_back(static_cast<int>(k));
  }
  return result;
}

}  // namespace kinematic_coverage::core
