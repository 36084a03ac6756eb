#include "polygon_coverage_ros_bridge/decomposition/sweep_line_decomposition.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <vector>

#include "polygon_coverage_ros_bridge/decomposition/sweep_direction.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// Relative tolerance: vertex positions along the sweep closer than this times the map
/// scale are snapped together, so that edges parallel to the lanes become exactly
/// vertical after the rotation into the sweep frame.
constexpr double kRelativeSnapTolerance = 1e-10;

/// A non-vertical boundary edge in the sweep frame, left end first.
struct Edge {
  Point2 left;
  Point2 right;
  std::size_t left_slab = 0;   // index of left.x() in the slab positions
  std::size_t right_slab = 0;  // index of right.x()
};

double yAt(const Edge& edge, double x) {
  if (x == edge.left.x()) return edge.left.y();
  if (x == edge.right.x()) return edge.right.y();
  const double t = (x - edge.left.x()) / (edge.right.x() - edge.left.x());
  return edge.left.y() + t * (edge.right.y() - edge.left.y());
}

/// The part of a slab between two consecutive boundary edges that is inside.
struct Trapezoid {
  std::size_t slab = 0;
  std::size_t bottom = 0;  // edge index
  std::size_t top = 0;     // edge index
  std::vector<std::size_t> left_neighbours;
  std::vector<std::size_t> right_neighbours;
  std::size_t cell = 0;
  /// CellJoining::kLongestOverlap: the left neighbour whose cell this one continues, and
  /// whether a right neighbour continues this one's.
  std::optional<std::size_t> continues;
  bool continued = false;
};

/// Drops repeated vertices and vertices lying on the segment between their neighbours.
Ring simplified(const Ring& ring, double tolerance) {
  Ring result;
  for (const Point2& p : ring) {
    if (result.empty() || (p - result.back()).norm() > tolerance) result.push_back(p);
  }
  while (result.size() > 1 && (result.front() - result.back()).norm() <= tolerance) {
    result.pop_back();
  }
  bool changed = true;
  while (changed && result.size() > 3) {
    changed = false;
    for (std::size_t i = 0; i < result.size() && result.size() > 3; ++i) {
      const std::size_t n = result.size();
      const Point2& prev = result[(i + n - 1) % n];
      const Point2& next = result[(i + 1) % n];
      if (distanceToSegment(result[i], prev, next) <= tolerance) {
        result.erase(result.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
      }
    }
  }
  return result;
}

/// The boundary edges that bound slabs (those not parallel to the lanes), with the slab
/// positions: the vertices' x-coordinates, those within `tolerance` of each other snapped
/// together (sweep frame).
struct SlabEdges {
  std::vector<Edge> edges;
  std::vector<double> slab_x;
};

SlabEdges slabEdges(std::vector<Ring>& rings, double tolerance) {
  std::vector<double> all_x;
  for (const Ring& ring : rings) {
    for (const Point2& p : ring) all_x.push_back(p.x());
  }
  std::sort(all_x.begin(), all_x.end());
  std::vector<double> representative(all_x.size());
  SlabEdges slabs;
  std::vector<double>& slab_x = slabs.slab_x;
  for (std::size_t i = 0; i < all_x.size(); ++i) {
    if (i == 0 || all_x[i] - slab_x.back() > tolerance) slab_x.push_back(all_x[i]);
    representative[i] = slab_x.back();
  }
  auto snap = [&](double x) {
    const auto it = std::lower_bound(all_x.begin(), all_x.end(), x);
    return representative[static_cast<std::size_t>(it - all_x.begin())];
  };
  auto slabIndex = [&](double x) {
    return static_cast<std::size_t>(std::lower_bound(slab_x.begin(), slab_x.end(), x) -
                                    slab_x.begin());
  };
  for (Ring& ring : rings) {
    for (Point2& p : ring) p.x() = snap(p.x());
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      const Point2& a = ring[i];
      const Point2& b = ring[(i + 1) % n];
      if (a.x() == b.x()) continue;  // parallel to the lanes: bounds no slab
      Edge edge;
      edge.left = a.x() < b.x() ? a : b;
      edge.right = a.x() < b.x() ? b : a;
      edge.left_slab = slabIndex(edge.left.x());
      edge.right_slab = slabIndex(edge.right.x());
      slabs.edges.push_back(edge);
    }
  }
  return slabs;
}

/// The trapezoids of every slab, bottom to top, and per slab the indices of its own.
struct SlabTrapezoids {
  std::vector<Trapezoid> trapezoids;
  std::vector<std::vector<std::size_t>> of_slab;
};

SlabTrapezoids slabTrapezoids(const SlabEdges& slabs) {
  const std::vector<Edge>& edges = slabs.edges;
  const std::size_t slab_count = slabs.slab_x.size() - 1;
  std::vector<std::vector<std::size_t>> active(slab_count);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    for (std::size_t s = edges[e].left_slab; s < edges[e].right_slab; ++s) active[s].push_back(e);
  }
  SlabTrapezoids result;
  result.of_slab.resize(slab_count);
  for (std::size_t s = 0; s < slab_count; ++s) {
    const double x_mid = 0.5 * (slabs.slab_x[s] + slabs.slab_x[s + 1]);
    std::vector<std::size_t>& slab_edges = active[s];
    std::sort(slab_edges.begin(), slab_edges.end(), [&](std::size_t a, std::size_t b) {
      return yAt(edges[a], x_mid) < yAt(edges[b], x_mid);
    });
    if (slab_edges.size() % 2 != 0) {
      std::ostringstream message;
      message << "cell decomposition failed: the area's boundary is not closed or crosses "
                 "itself near sweep position "
              << x_mid;
      throw InvalidInputError(message.str());
    }
    for (std::size_t k = 0; k + 1 < slab_edges.size(); k += 2) {
      Trapezoid trapezoid;
      trapezoid.slab = s;
      trapezoid.bottom = slab_edges[k];
      trapezoid.top = slab_edges[k + 1];
      result.of_slab[s].push_back(result.trapezoids.size());
      result.trapezoids.push_back(trapezoid);
    }
  }
  return result;
}

/// Two trapezoids connected across a slab boundary, and the length of their shared slice.
struct Connection {
  double overlap = 0.0;
  std::size_t left = 0;
  std::size_t right = 0;
};

/// Picks, longest shared slice first, which connections continue a cell: each trapezoid
/// continues at most one left neighbour's cell and is continued by at most one right
/// neighbour (a greedy matching, so cells stay chains of one trapezoid per slab).
void chooseContinuations(std::vector<Connection> connections, std::vector<Trapezoid>* trapezoids) {
  std::stable_sort(connections.begin(), connections.end(),
                   [](const Connection& a, const Connection& b) { return a.overlap > b.overlap; });
  for (const Connection& connection : connections) {
    Trapezoid& left = (*trapezoids)[connection.left];
    Trapezoid& right = (*trapezoids)[connection.right];
    if (left.continued || right.continues) continue;
    right.continues = connection.left;
    left.continued = true;
  }
}

/// Connects the trapezoids across each slab boundary whose intervals on the shared line
/// overlap by more than `tolerance`; with CellJoining::kLongestOverlap also chooses which
/// connections continue a cell.
void connectAcrossSlabs(const SlabEdges& slabs, double tolerance, CellJoining joining,
                        SlabTrapezoids* slab_trapezoids) {
  std::vector<Trapezoid>& trapezoids = slab_trapezoids->trapezoids;
  const std::vector<Edge>& edges = slabs.edges;
  for (std::size_t s = 0; s + 2 < slabs.slab_x.size(); ++s) {
    const double x = slabs.slab_x[s + 1];
    const auto& lefts = slab_trapezoids->of_slab[s];
    const auto& rights = slab_trapezoids->of_slab[s + 1];
    std::vector<Connection> connections;
    std::size_t i = 0;
    std::size_t j = 0;
    while (i < lefts.size() && j < rights.size()) {
      Trapezoid& l = trapezoids[lefts[i]];
      Trapezoid& r = trapezoids[rights[j]];
      const double l_lo = yAt(edges[l.bottom], x);
      const double l_hi = yAt(edges[l.top], x);
      const double r_lo = yAt(edges[r.bottom], x);
      const double r_hi = yAt(edges[r.top], x);
      const double overlap = std::min(l_hi, r_hi) - std::max(l_lo, r_lo);
      if (overlap > tolerance) {
        l.right_neighbours.push_back(rights[j]);
        r.left_neighbours.push_back(lefts[i]);
        connections.push_back({overlap, lefts[i], rights[j]});
      }
      if (l_hi < r_hi) {
        ++i;
      } else {
        ++j;
      }
    }
    if (joining == CellJoining::kLongestOverlap) chooseContinuations(connections, &trapezoids);
  }
}

/// Joins trapezoids into cells, left to right: a trapezoid continues its left neighbour's
/// cell when each is the other's only neighbour (boustrophedon) and, for trapezoidal
/// cells, when both lie between the same two edges; with CellJoining::kLongestOverlap
/// (boustrophedon only) a trapezoid continues the cell chosen by chooseContinuations.
/// Returns the cells' trapezoids.
std::vector<std::vector<std::size_t>> joinIntoCells(DecompositionType type, CellJoining joining,
                                                    SlabTrapezoids* slab_trapezoids) {
  std::vector<Trapezoid>& trapezoids = slab_trapezoids->trapezoids;
  std::vector<std::vector<std::size_t>> cells;
  for (const std::vector<std::size_t>& slab : slab_trapezoids->of_slab) {
    for (std::size_t t : slab) {
      Trapezoid& trapezoid = trapezoids[t];
      bool joined = false;
      if (joining == CellJoining::kLongestOverlap) {
        joined = trapezoid.continues.has_value();
        if (joined) trapezoid.cell = trapezoids[*trapezoid.continues].cell;
      } else if (trapezoid.left_neighbours.size() == 1) {
        const Trapezoid& left = trapezoids[trapezoid.left_neighbours.front()];
        joined = left.right_neighbours.size() == 1;
        if (type == DecompositionType::kTrapezoidal) {
          joined = joined && left.bottom == trapezoid.bottom && left.top == trapezoid.top;
        }
        if (joined) trapezoid.cell = left.cell;
      }
      if (!joined) {
        trapezoid.cell = cells.size();
        cells.emplace_back();
      }
      cells[trapezoid.cell].push_back(t);
    }
  }
  return cells;
}

/// A cell's outline (sweep frame): the bottom chain left to right, then the top chain right
/// to left. Both ends of every trapezoid are kept: where a bounding edge ends on a slab
/// boundary parallel to the lanes, the outline steps along that boundary.
Ring cellOutline(const std::vector<std::size_t>& cell, const SlabEdges& slabs,
                 const std::vector<Trapezoid>& trapezoids) {
  Ring ring;
  for (std::size_t t : cell) {
    const Trapezoid& trapezoid = trapezoids[t];
    for (double x : {slabs.slab_x[trapezoid.slab], slabs.slab_x[trapezoid.slab + 1]}) {
      ring.emplace_back(x, yAt(slabs.edges[trapezoid.bottom], x));
    }
  }
  for (auto it = cell.rbegin(); it != cell.rend(); ++it) {
    const Trapezoid& trapezoid = trapezoids[*it];
    for (double x : {slabs.slab_x[trapezoid.slab + 1], slabs.slab_x[trapezoid.slab]}) {
      ring.emplace_back(x, yAt(slabs.edges[trapezoid.top], x));
    }
  }
  return ring;
}

}  // namespace

std::vector<Ring> SweepLineDecomposition::decompose(const PolygonWithHoles& polygon,
                                                    double direction) const {
  // Rings in the sweep frame.
  std::vector<Ring> rings;
  rings.push_back(polygon.hull);
  rings.insert(rings.end(), polygon.holes.begin(), polygon.holes.end());
  double scale = 1.0;
  for (Ring& ring : rings) {
    for (Point2& p : ring) {
      p = toSweepFrame(p, direction);
      scale = std::max(scale, p.cwiseAbs().maxCoeff());
    }
  }
  const double tolerance = kRelativeSnapTolerance * scale;
  const SlabEdges slabs = slabEdges(rings, tolerance);
  if (slabs.slab_x.size() < 2) return {};
  SlabTrapezoids slab_trapezoids = slabTrapezoids(slabs);
  connectAcrossSlabs(slabs, tolerance, joining_, &slab_trapezoids);
  std::vector<Ring> result;
  for (const auto& cell : joinIntoCells(type_, joining_, &slab_trapezoids)) {
    Ring ring = simplified(cellOutline(cell, slabs, slab_trapezoids.trapezoids), tolerance);
    if (ring.size() < 3) continue;
    for (Point2& p : ring) p = fromSweepFrame(p, direction);
    result.push_back(std::move(ring));
  }
  return result;
}

}  // namespace kinematic_coverage::core
