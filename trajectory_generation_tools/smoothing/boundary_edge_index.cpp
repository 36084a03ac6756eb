#include "trajectory_generation_tools/smoothing/boundary_edge_index.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

/// Grid cells per indexed edge (about); more cells, fewer edges per query.
constexpr double kCellsPerEdge = 4.0;
/// Upper bound on the grid's columns and rows.
constexpr int kMaxCellsPerAxis = 2048;

CGAL::Orientation orientation(const Point2& a, const Point2& b, const Point2& c) {
  return CGAL::orientation(Kernel::Point_2(a.x(), a.y()), Kernel::Point_2(b.x(), b.y()),
                           Kernel::Point_2(c.x(), c.y()));
}

/// True when the open segments (a, b) and (p, q) cross at one interior point (exact).
/// Touching configurations have an endpoint on the other segment and are caught by the
/// endpoint distances.
bool properlyCross(const Point2& a, const Point2& b, const Point2& p, const Point2& q) {
  const CGAL::Orientation o1 = orientation(a, b, p);
  const CGAL::Orientation o2 = orientation(a, b, q);
  if (o1 == CGAL::COLLINEAR || o2 == CGAL::COLLINEAR || o1 == o2) return false;
  const CGAL::Orientation o3 = orientation(p, q, a);
  const CGAL::Orientation o4 = orientation(p, q, b);
  return o3 != CGAL::COLLINEAR && o4 != CGAL::COLLINEAR && o3 != o4;
}

double segmentSegmentDistance(const Point2& a, const Point2& b, const Point2& p, const Point2& q) {
  if (properlyCross(a, b, p, q)) return 0.0;
  return std::min({distanceToSegment(a, p, q), distanceToSegment(b, p, q),
                   distanceToSegment(p, a, b), distanceToSegment(q, a, b)});
}

/// True when the polar angle `angle` about the arc's centre lies within its sweep.
bool withinSweep(const PathPrimitive& arc, double angle) {
  const double sweep = arc.sweep();
  double offset = sweep >= 0.0 ? angle - arc.startAngle() : arc.startAngle() - angle;
  offset = std::fmod(offset, 2.0 * M_PI);
  if (offset < 0.0) offset += 2.0 * M_PI;
  return offset <= std::abs(sweep);
}

double pointArcDistance(const Point2& p, const PathPrimitive& arc) {
  const Point2 rel = p - arc.centre();
  const double distance = rel.norm();
  if (distance > 0.0 && withinSweep(arc, std::atan2(rel.y(), rel.x()))) {
    return std::abs(distance - arc.radius());
  }
  return std::min((p - arc.start()).norm(), (p - arc.end()).norm());
}

/// Exact-in-doubles distance between an arc and the segment [p, q]: the minimum over the
/// endpoint-to-other-piece distances and the interior critical points (the circle point
/// facing the segment's line, or the line's crossings with the circle).
double arcSegmentDistance(const PathPrimitive& arc, const Point2& p, const Point2& q) {
  double best =
      std::min({pointArcDistance(p, arc), pointArcDistance(q, arc),
                distanceToSegment(arc.start(), p, q), distanceToSegment(arc.end(), p, q)});
  const Point2 direction = q - p;
  const double length_sq = direction.squaredNorm();
  if (!(length_sq > 0.0)) return best;
  const Point2& centre = arc.centre();
  const double r = arc.radius();
  const double t_foot = (centre - p).dot(direction) / length_sq;
  const Point2 foot = p + t_foot * direction;
  const Point2 to_foot = foot - centre;
  const double h = to_foot.norm();
  if (h >= r) {
    if (t_foot >= 0.0 && t_foot <= 1.0 && withinSweep(arc, std::atan2(to_foot.y(), to_foot.x()))) {
      best = std::min(best, h - r);
    }
    return best;
  }
  const double half_chord = std::sqrt(std::max(0.0, r * r - h * h) / length_sq);
  for (const double t : {t_foot - half_chord, t_foot + half_chord}) {
    if (t < 0.0 || t > 1.0) continue;
    const Point2 rel = p + t * direction - centre;
    if (withinSweep(arc, std::atan2(rel.y(), rel.x()))) return 0.0;
  }
  return best;
}

}  // namespace

BoundaryEdgeIndex::BoundaryEdgeIndex(const PolygonWithHoles& free_area, double clearance) {
  if (!std::isfinite(clearance) || clearance < 0.0) {
    throw InvalidInputError("smoothing clearance must be a finite number >= 0, got " +
                            std::to_string(clearance));
  }
  clearance_ = std::max(kContactTolerance, clearance);
  blocking_distance_ = std::max(kContactTolerance, clearance - kClearanceTolerance);
  auto add_ring = [this](const Ring& ring) {
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      const Point2& from = ring[i];
      const Point2& to = ring[(i + 1) % n];
      if (!from.allFinite()) {
        throw InvalidInputError("free area: a ring vertex has a non-finite coordinate");
      }
      if (from == to) continue;
      from_.push_back(from);
      to_.push_back(to);
    }
  };
  has_hull_ = free_area.hull.size() >= 3;
  if (has_hull_) add_ring(free_area.hull);
  for (const Ring& hole : free_area.holes) add_ring(hole);
  EdgeGrid::Layout layout;
  layout.cells_per_edge = kCellsPerEdge;
  layout.max_cells_per_axis = kMaxCellsPerAxis;
  grid_ = EdgeGrid(from_, to_, layout);
}

void BoundaryEdgeIndex::edgesNear(const Point2& low, const Point2& high,
                                  std::vector<int>* ids) const {
  const Point2 margin = Point2::Constant(clearance_);
  grid_.collect(grid_.cellsOf(low - margin, high + margin), ids);
}

bool BoundaryEdgeIndex::segmentClear(const Point2& a, const Point2& b) const {
  std::vector<int> ids;
  edgesNear(a.cwiseMin(b), a.cwiseMax(b), &ids);
  for (const int id : ids) {
    if (segmentSegmentDistance(a, b, from_[id], to_[id]) <= blocking_distance_) {
      return false;
    }
  }
  return true;
}

bool BoundaryEdgeIndex::arcClear(const PathPrimitive& arc) const {
  const Point2 reach(arc.radius(), arc.radius());
  std::vector<int> ids;
  edgesNear(arc.centre() - reach, arc.centre() + reach, &ids);
  for (const int id : ids) {
    if (arcSegmentDistance(arc, from_[id], to_[id]) <= blocking_distance_) {
      return false;
    }
  }
  return true;
}

bool BoundaryEdgeIndex::primitiveClear(const PathPrimitive& primitive) const {
  switch (primitive.kind()) {
    case PrimitiveKind::kArc:
      return arcClear(primitive);
    case PrimitiveKind::kSegment:
      return segmentClear(primitive.start(), primitive.end());
    case PrimitiveKind::kRotation:
      return segmentClear(primitive.start(), primitive.start());
    case PrimitiveKind::kClothoid: {
      const std::vector<Point2> chords = primitive.polyline(kClothoidChordTolerance);
      for (std::size_t i = 1; i < chords.size(); ++i) {
        if (!segmentClear(chords[i - 1], chords[i])) return false;
      }
      return true;
    }
  }
  return false;
}

bool BoundaryEdgeIndex::inside(const Point2& p) const {
  if (from_.empty()) return true;
  // Even-odd count along the axis ray that crosses the fewest grid cells; the edges it can
  // meet are those registered in the cells of its strip. Off the grid, p is outside every
  // ring.
  int crossings = 0;
  if (grid_.covers(p)) {
    const int column = grid_.column(p.x());
    const int row = grid_.row(p.y());
    const int to_right = grid_.columns() - 1 - column;
    const int to_top = grid_.rows() - 1 - row;
    const int shortest = std::min({to_right, column, to_top, row});
    const bool horizontal = shortest == to_right || shortest == column;
    const bool positive = shortest == to_right || (!horizontal && shortest == to_top);
    EdgeGrid::CellRange strip{column, row, column, row};
    if (horizontal) {
      (positive ? strip.x1 : strip.x0) = positive ? grid_.columns() - 1 : 0;
    } else {
      (positive ? strip.y1 : strip.y0) = positive ? grid_.rows() - 1 : 0;
    }
    std::vector<int> ids;
    grid_.collect(strip, &ids);
    // Along the ray's axis `a` with the other axis `o`: the half-open rule counts an edge
    // when its endpoints lie on different sides of the ray's line.
    const int a = horizontal ? 0 : 1;
    const int o = 1 - a;
    for (const int id : ids) {
      const Point2& e0 = from_[id];
      const Point2& e1 = to_[id];
      if ((e0[o] > p[o]) == (e1[o] > p[o])) continue;
      const double at = e0[a] + (p[o] - e0[o]) * (e1[a] - e0[a]) / (e1[o] - e0[o]);
      if (positive ? at > p[a] : at < p[a]) ++crossings;
    }
  }
  const bool odd = (crossings % 2) == 1;
  return has_hull_ ? odd : !odd;
}

}  // namespace kinematic_coverage::core
