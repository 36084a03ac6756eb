#pragma once

#include <algorithm>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// Straight edges bucketed in a uniform grid over their bounding box: the one spatial
/// index of boundary edges, under the transition router's visibility test (BoundaryGrid)
/// and the smoother's collision test (BoundaryEdgeIndex). A query visits only the edges
/// registered in the cells it meets. Every cell lookup, for registering an edge and for a
/// query, goes through the same monotone column and row functions, so a query meeting an
/// edge's (grown) box always finds the edge. Immutable after construction.
class EdgeGrid {
 public:
  /// How the grid is laid out over the edges.
  struct Layout {
    double cells_per_edge = 2.0;  ///< about this many cells per edge
    int max_cells_per_axis = 512;
    double margin = 0.0;   ///< the grid covers the edges' box grown by this (m)
    double padding = 0.0;  ///< each edge is registered in the cells its box grown by this meets
  };

  /// A rectangle of cells, inclusive; empty when x0 > x1 or y0 > y1.
  struct CellRange {
    int x0, y0, x1, y1;
    bool empty() const { return x0 > x1 || y0 > y1; }
  };

  /// An empty grid: its queries find nothing.
  EdgeGrid() = default;

  /// Edge i runs from starts[i] to ends[i] (finite coordinates). No edges: an empty grid
  /// whose queries find nothing.
  EdgeGrid(const std::vector<Point2>& starts, const std::vector<Point2>& ends,
           const Layout& layout);

  /// The column of x and the row of y, clamped into the grid (inline: the router's and
  /// the smoother's innermost loops call them).
  int column(double x) const {
    const double c = (x - origin_.x()) * inverse_cell_width_;
    return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(columns_) - 0.5));
  }
  int row(double y) const {
    const double r = (y - origin_.y()) * inverse_cell_height_;
    return static_cast<int>(std::clamp(r, 0.0, static_cast<double>(rows_) - 0.5));
  }
  int columns() const { return columns_; }
  int rows() const { return rows_; }

  /// True when p lies in the grid's rectangle (boundary included).
  bool covers(const Point2& p) const;

  /// The cells of the box [low, high]; empty when the box misses the grid.
  CellRange cellsOf(const Point2& low, const Point2& high) const;

  /// The edges registered in the cell (column, row), in ascending order: [first, last).
  const int* cellBegin(int column, int row) const {
    return cell_edges_.data() + cell_begin_[static_cast<std::size_t>(row) * columns_ + column];
  }
  const int* cellEnd(int column, int row) const {
    return cell_edges_.data() + cell_begin_[static_cast<std::size_t>(row) * columns_ + column + 1];
  }

  /// The distinct edges registered in the cells of `range`, ascending.
  void collect(const CellRange& range, std::vector<int>* ids) const;

  /// Calls visit(edge) for the edges registered in the cells the segment [a, b] meets,
  /// row by row (an edge may come more than once); stops and returns false as soon as
  /// visit returns false.
  template <typename Visit>
  bool visitEdgesAlong(const Point2& a, const Point2& b, Visit&& visit) const;

 private:
  Point2 origin_ = Point2::Zero();
  Point2 size_ = Point2::Zero();
  double cell_width_ = 1.0;
  double cell_height_ = 1.0;
  double inverse_cell_width_ = 1.0;
  double inverse_cell_height_ = 1.0;
  int columns_ = 0;
  int rows_ = 0;
  std::vector<int>
      cell_begin_;  ///< edges of cell c: cell_edges_[cell_begin_[c], cell_begin_[c + 1])
  std::vector<int> cell_edges_;
};

template <typename Visit>
bool EdgeGrid::visitEdgesAlong(const Point2& a, const Point2& b, Visit&& visit) const {
  if (columns_ == 0) return true;
  // Row by row, the columns the segment spans within the row's band.
  const double y_low = std::min(a.y(), b.y());
  const double y_high = std::max(a.y(), b.y());
  const double x_low = std::min(a.x(), b.x());
  const double x_high = std::max(a.x(), b.x());
  const double dy = b.y() - a.y();
  const double slope = dy != 0.0 ? (b.x() - a.x()) / dy : 0.0;
  for (int r = row(y_low), last_row = row(y_high); r <= last_row; ++r) {
    double from = x_low;
    double to = x_high;
    if (dy != 0.0) {
      const double band_low = std::max(y_low, origin_.y() + r * cell_height_);
      const double band_high = std::min(y_high, origin_.y() + (r + 1) * cell_height_);
      const double x1 = a.x() + (band_low - a.y()) * slope;
      const double x2 = a.x() + (band_high - a.y()) * slope;
      from = std::clamp(std::min(x1, x2), x_low, x_high);
      to = std::clamp(std::max(x1, x2), x_low, x_high);
    }
    for (int c = column(from), last_column = column(to); c <= last_column; ++c) {
      for (const int* edge = cellBegin(c, r); edge != cellEnd(c, r); ++edge) {
        if (!visit(*edge)) return false;
      }
    }
  }
  return true;
}

}  // namespace kinematic_coverage::core
