#include "trajectory_generation_tools/smoothing/boundary_edge_index.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>

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

BoundaryEdgeIndex::BoundaryEdgeIndex(const PolygonWithHoles& free_area) {
  auto add_ring = [this](const Ring& ring) {
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      const Point2& from = ring[i];
      const Point2& to = ring[(i + 1) % n];
      if (!from.allFinite()) {
        throw InvalidInputError("free area: a ring vertex has a non-finite coordinate");
      }
      if (from != to) edges_.push_back({from, to});
    }
  };
  has_hull_ = free_area.hull.size() >= 3;
  if (has_hull_) add_ring(free_area.hull);
  for (const Ring& hole : free_area.holes) add_ring(hole);
  if (edges_.empty()) return;

  Point2 low = edges_.front().from;
  Point2 high = low;
  for (const Edge& edge : edges_) {
    low = low.cwiseMin(edge.from).cwiseMin(edge.to);
    high = high.cwiseMax(edge.from).cwiseMax(edge.to);
  }
  const Point2 extent = (high - low).cwiseMax(Point2(1e-9, 1e-9));
  const double target_cells = kCellsPerEdge * static_cast<double>(edges_.size());
  const double cell = std::sqrt(extent.x() * extent.y() / target_cells);
  columns_ = std::clamp(static_cast<int>(std::ceil(extent.x() / cell)), 1, kMaxCellsPerAxis);
  rows_ = std::clamp(static_cast<int>(std::ceil(extent.y() / cell)), 1, kMaxCellsPerAxis);
  origin_ = low;
  cell_width_ = extent.x() / columns_;
  cell_height_ = extent.y() / rows_;

  // Compressed rows: count the edges per cell, then fill.
  const std::size_t cell_count = static_cast<std::size_t>(columns_) * rows_;
  std::vector<std::uint32_t> counts(cell_count + 1, 0);
  std::vector<CellRange> ranges;
  ranges.reserve(edges_.size());
  for (const Edge& edge : edges_) {
    ranges.push_back(cellsOf(edge.from.cwiseMin(edge.to), edge.from.cwiseMax(edge.to)));
    const CellRange& range = ranges.back();
    for (int y = range.y0; y <= range.y1; ++y) {
      for (int x = range.x0; x <= range.x1; ++x)
        ++counts[static_cast<std::size_t>(y) * columns_ + x];
    }
  }
  cell_start_.assign(cell_count + 1, 0);
  for (std::size_t i = 0; i < cell_count; ++i) cell_start_[i + 1] = cell_start_[i] + counts[i];
  cell_edges_.resize(cell_start_.back());
  std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (std::uint32_t id = 0; id < edges_.size(); ++id) {
    const CellRange& range = ranges[id];
    for (int y = range.y0; y <= range.y1; ++y) {
      for (int x = range.x0; x <= range.x1; ++x) {
        cell_edges_[fill[static_cast<std::size_t>(y) * columns_ + x]++] = id;
      }
    }
  }
}

BoundaryEdgeIndex::CellRange BoundaryEdgeIndex::cellsOf(const Point2& low,
                                                        const Point2& high) const {
  if (columns_ == 0) return {0, 0, -1, -1};
  // Widened by the contact tolerance so that edges just outside the box still count.
  const double margin = kContactTolerance;
  const double x0 = (low.x() - margin - origin_.x()) / cell_width_;
  const double x1 = (high.x() + margin - origin_.x()) / cell_width_;
  const double y0 = (low.y() - margin - origin_.y()) / cell_height_;
  const double y1 = (high.y() + margin - origin_.y()) / cell_height_;
  if (!(x1 >= 0.0 && y1 >= 0.0 && x0 < columns_ && y0 < rows_)) return {0, 0, -1, -1};
  // Clamped as doubles before the cast, so far-away boxes cannot overflow an int.
  return {static_cast<int>(std::max(0.0, std::floor(x0))),
          static_cast<int>(std::max(0.0, std::floor(y0))),
          static_cast<int>(std::min(columns_ - 1.0, std::floor(x1))),
          static_cast<int>(std::min(rows_ - 1.0, std::floor(y1)))};
}

void BoundaryEdgeIndex::collect(const CellRange& range, std::vector<std::uint32_t>* ids) const {
  ids->clear();
  if (range.empty()) return;
  for (int y = range.y0; y <= range.y1; ++y) {
    const std::size_t row_start = static_cast<std::size_t>(y) * columns_;
    ids->insert(ids->end(), cell_edges_.begin() + cell_start_[row_start + range.x0],
                cell_edges_.begin() + cell_start_[row_start + range.x1 + 1]);
  }
  std::sort(ids->begin(), ids->end());
  ids->erase(std::unique(ids->begin(), ids->end()), ids->end());
}

bool BoundaryEdgeIndex::segmentClear(const Point2& a, const Point2& b) const {
  std::vector<std::uint32_t> ids;
  collect(cellsOf(a.cwiseMin(b), a.cwiseMax(b)), &ids);
  for (const std::uint32_t id : ids) {
    if (segmentSegmentDistance(a, b, edges_[id].from, edges_[id].to) <= kContactTolerance) {
      return false;
    }
  }
  return true;
}

bool BoundaryEdgeIndex::arcClear(const PathPrimitive& arc) const {
  const Point2 reach(arc.radius(), arc.radius());
  std::vector<std::uint32_t> ids;
  collect(cellsOf(arc.centre() - reach, arc.centre() + reach), &ids);
  for (const std::uint32_t id : ids) {
    if (arcSegmentDistance(arc, edges_[id].from, edges_[id].to) <= kContactTolerance) {
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
  }
  return false;
}

bool BoundaryEdgeIndex::inside(const Point2& p) const {
  if (edges_.empty()) return true;
  // Even-odd count along the axis ray that crosses the fewest grid cells; the edges it can
  // meet are those registered in the cells of its strip.
  const double column_at = std::floor((p.x() - origin_.x()) / cell_width_);
  const double row_at = std::floor((p.y() - origin_.y()) / cell_height_);
  int crossings = 0;
  if (column_at >= 0.0 && column_at < columns_ && row_at >= 0.0 && row_at < rows_) {
    const int column = static_cast<int>(column_at);
    const int row = static_cast<int>(row_at);
    const int to_right = columns_ - 1 - column;
    const int to_top = rows_ - 1 - row;
    const int shortest = std::min({to_right, column, to_top, row});
    const bool horizontal = shortest == to_right || shortest == column;
    const bool positive = shortest == to_right || (!horizontal && shortest == to_top);
    CellRange strip{column, row, column, row};
    if (horizontal) {
      (positive ? strip.x1 : strip.x0) = positive ? columns_ - 1 : 0;
    } else {
      (positive ? strip.y1 : strip.y0) = positive ? rows_ - 1 : 0;
    }
    std::vector<std::uint32_t> ids;
    collect(strip, &ids);
    // Along the ray's axis `a` with the other axis `o`: the half-open rule counts an edge
    // when its endpoints lie on different sides of the ray's line.
    const int a = horizontal ? 0 : 1;
    const int o = 1 - a;
    for (const std::uint32_t id : ids) {
      const Point2& e0 = edges_[id].from;
      const Point2& e1 = edges_[id].to;
      if ((e0[o] > p[o]) == (e1[o] > p[o])) continue;
      const double at = e0[a] + (p[o] - e0[o]) * (e1[a] - e0[a]) / (e1[o] - e0[o]);
      if (positive ? at > p[a] : at < p[a]) ++crossings;
    }
  }
  const bool odd = (crossings % 2) == 1;
  return has_hull_ ? odd : !odd;
}

}  // namespace kinematic_coverage::core
