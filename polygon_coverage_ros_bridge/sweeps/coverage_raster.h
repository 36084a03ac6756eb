#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// One value per raster cell, row-major from the grid's minimum corner: 1 where the cell's
/// centre lies in the area the mask stands for, 0 elsewhere.
using CellMask = std::vector<std::uint8_t>;

/// One value per raster cell, row-major: the share of the cell's area inside an area, in
/// [0, 1] (CoverageRaster::areaFractions).
using CellFractions = std::vector<float>;

/// The cells [begin, end) of one raster row whose centres lie in a rasterized area.
struct CellSpan {
  int row = 0;
  int begin = 0;
  int end = 0;
};

/// How fine a CoverageRaster should be.
struct RasterResolution {
  /// Cell edge length in metres; 0 chooses it from `relative_accuracy` and `max_cells`.
  double cell_size = 0.0;
  /// Wanted bound on a rasterized region's area error, relative to its area. Sampling
  /// cell centres misplaces each boundary point by at most half a cell, so the error is at
  /// most perimeter * cell_size / 2; the automatic cell size keeps that below this share.
  double relative_accuracy = 1e-3;
  /// Largest grid: an automatic cell size is coarsened to fit it (boundary errors then
  /// mostly cancel, so the typical error stays far below the bound); an explicit cell
  /// size that needs more cells is rejected. At least 9 (3 x 3 cells).
  std::size_t max_cells = 4'000'000;
  /// Finest automatic cell size in metres (0: no floor). The accuracy bound above is a
  /// worst case that small maps meet only with very fine cells, whose count, and so the
  /// evaluation time, grows with the inverse square of the size; a floor keeps them
  /// affordable where a coarser grid is already accurate enough.
  double min_cell_size = 0.0;
  /// The floor gives way, down to the cell size at which the grid has this many cells (0:
  /// never): a small map gets fine cells while they are cheap, since the floor would leave
  /// its error above the accuracy asked for (a 34 m^2 comb of narrow bays at 5 cm cells is
  /// off by 0.4 %).
  std::size_t floor_cells = 0;
};

/// A grid of square cells over a bounding box, on which areas are sampled at the cell
/// centres (even-odd scanline rasterization). Coverage is counted
/// on it in pure doubles, with no exact geometry, so that evaluating a map is fast.
class CoverageRaster {
 public:
  /// A grid whose cell (row 0, column 0) has its minimum corner at `origin`.
  /// Throws InvalidInputError for a non-finite origin, a cell size <= 0 or an empty grid.
  CoverageRaster(const Point2& origin, double cell_size, int columns, int rows);

  /// The grid over the hull's bounding box (plus one cell each side) at `resolution`.
  /// Throws InvalidInputError for a region without area, non-finite coordinates, a
  /// resolution out of range, or an explicit cell size that needs more than `max_cells`.
  static CoverageRaster covering(const PolygonWithHoles& region,
                                 const RasterResolution& resolution = {});

  const Point2& origin() const { return origin_; }
  double cellSize() const { return cell_size_; }
  double cellArea() const { return cell_size_ * cell_size_; }
  int columns() const { return columns_; }
  int rows() const { return rows_; }
  std::size_t cellCount() const {
    return static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_);
  }
  /// Row-major index of a cell.
  std::size_t index(int row, int column) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_) +
           static_cast<std::size_t>(column);
  }
  /// Centre of the cell with row-major index `index`.
  Point2 cellCentre(std::size_t index) const;

  /// The cells whose centres lie in the polygon (even-odd over hull and holes; a centre
  /// exactly on a left or bottom edge is in, on a right or top edge out, so areas that
  /// tile the plane share no cell). Throws InvalidInputError for non-finite coordinates.
  CellMask rasterize(const PolygonWithHoles& polygon) const;

  /// The cells whose centres lie in any of the polygons (the union of their rasterizations).
  CellMask rasterize(const std::vector<PolygonWithHoles>& polygons) const;

  /// Lines per cell row on which areaFractions measures the boundary cells.
  static constexpr int kFractionLines = 16;

  /// The share of every cell's area inside the polygon: 1 or 0 away from its boundary, and
  /// for each cell the boundary passes through, the mean over kFractionLines horizontal
  /// lines across the cell of the length inside (exact along each line). Sums to the
  /// polygon's area within perimeter * cell_size / (2 kFractionLines), 16 times closer than
  /// rasterize's centre samples: a coverage share over this weight has no bias from a
  /// boundary that runs along the grid (a rectilinear harbour). Throws InvalidInputError
  /// for non-finite coordinates.
  CellFractions areaFractions(const PolygonWithHoles& polygon) const;

  /// Appends to `spans` the row spans of the cells whose centres lie in the convex
  /// polygon `convex` (same edge rules as rasterize), in the rows [first_row, end_row) only
  /// (a band of the grid); fast for a few vertices.
  void appendConvexSpans(const Ring& convex, std::vector<CellSpan>& spans, int first_row = 0,
                         int end_row = std::numeric_limits<int>::max()) const;

  /// Number of set (non-zero) cells of a mask.
  static std::size_t countCells(const CellMask& mask);

  /// Area of a mask in square metres.
  double area(const CellMask& mask) const { return countCells(mask) * cellArea(); }

 private:
  /// First row whose centre y is >= y (clamped to [0, rows]).
  int firstRowAtOrAbove(double y) const;
  /// First column whose centre x is >= x (clamped to [0, columns]).
  int firstColumnAtOrRightOf(double x) const;
  /// Centre y of a row.
  double rowCentre(int row) const { return origin_.y() + (row + 0.5) * cell_size_; }

  Point2 origin_;
  double cell_size_;
  int columns_;
  int rows_;
};

}  // namespace kinematic_coverage::core
