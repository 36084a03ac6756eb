#include "polygon_coverage_ros_bridge/sweeps/coverage_raster.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>
#include <sstream>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// Largest coordinate magnitude (metres) accepted, far beyond any map, so that no
/// difference of coordinates overflows.
constexpr double kMaxCoordinate = 1e15;

/// Smallest cell budget: any region fits a grid of 3 x 3 cells (one cell plus the margin
/// each side), so that growing the cell size always ends.
constexpr std::size_t kMinCells = 9;

/// Factor by which an automatic cell size grows until its grid fits the cell budget.
constexpr double kCellSizeGrowth = 1.01;

void requireFinite(const Ring& ring, const char* what) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (!(std::abs(ring[i].x()) <= kMaxCoordinate) || !(std::abs(ring[i].y()) <= kMaxCoordinate)) {
      std::ostringstream message;
      message << "coverage raster: " << what << " vertex " << i
              << " has a non-finite coordinate or one beyond " << kMaxCoordinate << " m";
      throw InvalidInputError(message.str());
    }
  }
}

void requireFinite(const PolygonWithHoles& polygon) {
  requireFinite(polygon.hull, "hull");
  for (const Ring& hole : polygon.holes) requireFinite(hole, "hole");
}

/// Orders an edge's ends by y (then x), so that crossings do not depend on edge direction.
bool lowerFirst(const Point2& p, const Point2& q) {
  return p.y() < q.y() || (p.y() == q.y() && p.x() < q.x());
}

/// x where the edge from `a` up to `b` (a.y <= y < b.y) crosses the line at height y;
/// interpolated by the edge's share below y, which stays in [0, 1] whatever the slope.
double crossingAt(const Point2& a, const Point2& b, double y) {
  return a.x() + (y - a.y()) / (b.y() - a.y()) * (b.x() - a.x());
}

double perimeter(const Ring& ring) {
  double length = 0.0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i)
    length += (ring[(i + 1) % n] - ring[i]).norm();
  return length;
}

/// Cells per axis of a grid of `cell_size` over `extent` plus one cell each side, as a
/// double so that absurd sizes are caught before any integer conversion.
double cellsAlong(double extent, double cell_size) { return std::ceil(extent / cell_size) + 2.0; }

}  // namespace

CoverageRaster::CoverageRaster(const Point2& origin, double cell_size, int columns, int rows)
    : origin_(origin), cell_size_(cell_size), columns_(columns), rows_(rows) {
  if (!std::isfinite(origin.x()) || !std::isfinite(origin.y())) {
    throw InvalidInputError("coverage raster: the origin has a non-finite coordinate");
  }
  if (!(cell_size > 0.0) || !std::isfinite(cell_size)) {
    std::ostringstream message;
    message << "coverage raster: cell size " << cell_size << " must be finite and > 0";
    throw InvalidInputError(message.str());
  }
  if (columns <= 0 || rows <= 0) {
    std::ostringstream message;
    message << "coverage raster: a grid of " << columns << " x " << rows << " cells is empty";
    throw InvalidInputError(message.str());
  }
}

CoverageRaster CoverageRaster::covering(const PolygonWithHoles& region,
                                        const RasterResolution& resolution) {
  requireFinite(region);
  if (region.hull.size() < 3) {
    throw InvalidInputError("coverage raster: the region's hull has fewer than 3 vertices");
  }
  const double region_area = kinematic_coverage::core::area(region);
  if (!(region_area > 0.0)) {
    throw InvalidInputError("coverage raster: the region has no area");
  }
  if (resolution.max_cells < kMinCells) {
    std::ostringstream message;
    message << "coverage raster: max_cells " << resolution.max_cells << " must be at least "
            << kMinCells;
    throw InvalidInputError(message.str());
  }
  Point2 low = region.hull.front();
  Point2 high = region.hull.front();
  for (const Point2& p : region.hull) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  const Point2 extent = high - low;
  const double budget = static_cast<double>(resolution.max_cells);
  const auto cells = [&](double h) {
    return cellsAlong(extent.x(), h) * cellsAlong(extent.y(), h);
  };

  double cell_size = resolution.cell_size;
  if (cell_size != 0.0) {
    if (!(cell_size > 0.0) || !std::isfinite(cell_size)) {
      std::ostringstream message;
      message << "coverage raster: cell size " << cell_size << " must be finite and > 0";
      throw InvalidInputError(message.str());
    }
    if (cells(cell_size) > budget) {
      std::ostringstream message;
      message << "coverage raster: cell size " << cell_size << " m needs " << cells(cell_size)
              << " cells, more than max_cells = " << resolution.max_cells;
      throw InvalidInputError(message.str());
    }
  } else {
    if (!(resolution.relative_accuracy > 0.0) || !std::isfinite(resolution.relative_accuracy)) {
      std::ostringstream message;
      message << "coverage raster: relative accuracy " << resolution.relative_accuracy
              << " must be finite and > 0";
      throw InvalidInputError(message.str());
    }
    if (!(resolution.min_cell_size >= 0.0) || !std::isfinite(resolution.min_cell_size)) {
      std::ostringstream message;
      message << "coverage raster: minimum cell size " << resolution.min_cell_size
              << " must be finite and >= 0";
      throw InvalidInputError(message.str());
    }
    double boundary_length = perimeter(region.hull);
    for (const Ring& hole : region.holes) boundary_length += perimeter(hole);
    cell_size = 2.0 * resolution.relative_accuracy * region_area / boundary_length;
    const double budget_cell_size = std::sqrt(extent.x() * extent.y() / budget);
    double floor = resolution.min_cell_size;
    if (resolution.floor_cells > 0) {
      floor = std::min(
          floor, std::sqrt(extent.x() * extent.y() / static_cast<double>(resolution.floor_cells)));
    }
    cell_size = std::max({cell_size, floor, budget_cell_size});
    while (cells(cell_size) > budget) cell_size *= kCellSizeGrowth;
  }
  const double columns = cellsAlong(extent.x(), cell_size);
  const double rows = cellsAlong(extent.y(), cell_size);
  if (columns > INT_MAX || rows > INT_MAX) {
    throw InvalidInputError("coverage raster: the grid has too many rows or columns");
  }
  return CoverageRaster(low - Point2(cell_size, cell_size), cell_size, static_cast<int>(columns),
                        static_cast<int>(rows));
}

Point2 CoverageRaster::cellCentre(std::size_t index) const {
  const std::size_t columns = static_cast<std::size_t>(columns_);
  const double column = static_cast<double>(index % columns);
  const double row = static_cast<double>(index / columns);
  return origin_ + cell_size_ * Point2(column + 0.5, row + 0.5);
}

int CoverageRaster::firstRowAtOrAbove(double y) const {
  const double row = std::ceil((y - origin_.y()) / cell_size_ - 0.5);
  if (!(row > 0.0)) return 0;  // also NaN
  return static_cast<int>(std::min(row, static_cast<double>(rows_)));
}

int CoverageRaster::firstColumnAtOrRightOf(double x) const {
  const double column = std::ceil((x - origin_.x()) / cell_size_ - 0.5);
  if (!(column > 0.0)) return 0;  // also NaN
  return static_cast<int>(std::min(column, static_cast<double>(columns_)));
}

CellMask CoverageRaster::rasterize(const std::vector<PolygonWithHoles>& polygons) const {
  CellMask mask(cellCount(), 0);
  for (const PolygonWithHoles& polygon : polygons) {
    const CellMask part = rasterize(polygon);
    for (std::size_t i = 0; i < part.size(); ++i) mask[i] |= part[i];
  }
  return mask;
}

CellMask CoverageRaster::rasterize(const PolygonWithHoles& polygon) const {
  requireFinite(polygon);
  std::vector<const Ring*> rings{&polygon.hull};
  for (const Ring& hole : polygon.holes) rings.push_back(&hole);

  // Edge table: each edge adds its crossing x to every row whose centre y lies in
  // [min y, max y) of the edge; first count per row, then fill a flat array.
  std::vector<std::size_t> row_start(static_cast<std::size_t>(rows_) + 1, 0);
  const auto forEachCrossing = [&](const auto& visit) {
    for (const Ring* ring : rings) {
      for (std::size_t i = 0, n = ring->size(); i < n; ++i) {
        // From the lower end, so that an edge shared by two rings crosses rows alike.
        const Point2& a = std::min((*ring)[i], (*ring)[(i + 1) % n], lowerFirst);
        const Point2& b = std::max((*ring)[i], (*ring)[(i + 1) % n], lowerFirst);
        if (a.y() == b.y()) continue;
        const int first = firstRowAtOrAbove(a.y());
        const int last = firstRowAtOrAbove(b.y());
        for (int row = first; row < last; ++row) visit(row, crossingAt(a, b, rowCentre(row)));
      }
    }
  };
  forEachCrossing([&](int row, double) { ++row_start[static_cast<std::size_t>(row) + 1]; });
  for (std::size_t row = 0; row < static_cast<std::size_t>(rows_); ++row) {
    row_start[row + 1] += row_start[row];
  }
  std::vector<double> crossings(row_start.back());
  std::vector<std::size_t> fill(row_start.begin(), row_start.end() - 1);
  forEachCrossing([&](int row, double x) { crossings[fill[static_cast<std::size_t>(row)]++] = x; });

  CellMask mask(cellCount(), 0);
  for (int row = 0; row < rows_; ++row) {
    const auto begin = crossings.begin() + static_cast<std::ptrdiff_t>(row_start[row]);
    const auto end = crossings.begin() + static_cast<std::ptrdiff_t>(row_start[row + 1]);
    std::sort(begin, end);
    // `end - it`, not `it + 1 < end`: an empty table's iterators are null.
    for (auto it = begin; end - it >= 2; it += 2) {
      const int first = firstColumnAtOrRightOf(*it);
      const int last = firstColumnAtOrRightOf(*(it + 1));
      if (first < last) {
        std::fill(mask.begin() + static_cast<std::ptrdiff_t>(index(row, first)),
                  mask.begin() + static_cast<std::ptrdiff_t>(index(row, last)), 1);
      }
    }
  }
  return mask;
}

CellFractions CoverageRaster::areaFractions(const PolygonWithHoles& polygon) const {
  const CellMask centres = rasterize(polygon);
  CellFractions fractions(centres.begin(), centres.end());
  std::vector<const Ring*> rings{&polygon.hull};
  for (const Ring& hole : polygon.holes) rings.push_back(&hole);
  // Per row, the edges that reach into it and the cells they pass through.
  std::vector<std::vector<std::pair<Point2, Point2>>> row_edges(static_cast<std::size_t>(rows_));
  std::vector<std::vector<int>> row_cells(static_cast<std::size_t>(rows_));
  const auto clampedRow = [&](double y) {
    const double row = std::floor((y - origin_.y()) / cell_size_);
    return static_cast<int>(std::clamp(row, 0.0, static_cast<double>(rows_ - 1)));
  };
  const auto clampedColumn = [&](double x) {
    const double column = std::floor((x - origin_.x()) / cell_size_);
    return static_cast<int>(std::clamp(column, 0.0, static_cast<double>(columns_ - 1)));
  };
  for (const Ring* ring : rings) {
    for (std::size_t i = 0, n = ring->size(); i < n; ++i) {
      const Point2& a = std::min((*ring)[i], (*ring)[(i + 1) % n], lowerFirst);
      const Point2& b = std::max((*ring)[i], (*ring)[(i + 1) % n], lowerFirst);
      for (int row = clampedRow(a.y()); row <= clampedRow(b.y()); ++row) {
        if (a.y() != b.y()) row_edges[static_cast<std::size_t>(row)].emplace_back(a, b);
        // The part of the edge within the row's band, and the cells under it.
        const double low = std::max(a.y(), origin_.y() + row * cell_size_);
        const double high = std::min(b.y(), origin_.y() + (row + 1) * cell_size_);
        double x0 = a.x();
        double x1 = b.x();
        if (a.y() != b.y()) {
          x0 = crossingAt(a, b, std::clamp(low, a.y(), b.y()));
          x1 = crossingAt(a, b, std::clamp(high, a.y(), b.y()));
        }
        std::vector<int>& cells = row_cells[static_cast<std::size_t>(row)];
        for (int column = clampedColumn(std::min(x0, x1));
             column <= clampedColumn(std::max(x0, x1)); ++column) {
          cells.push_back(column);
        }
      }
    }
  }
  std::vector<double> crossings;
  std::vector<double> inside;
  for (int row = 0; row < rows_; ++row) {
    std::vector<int>& cells = row_cells[static_cast<std::size_t>(row)];
    if (cells.empty()) continue;
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    inside.assign(cells.size(), 0.0);
    for (int line = 0; line < kFractionLines; ++line) {
      const double y = origin_.y() + (row + (line + 0.5) / kFractionLines) * cell_size_;
      crossings.clear();
      for (const auto& [a, b] : row_edges[static_cast<std::size_t>(row)]) {
        if (a.y() <= y && y < b.y()) crossings.push_back(crossingAt(a, b, y));
      }
      std::sort(crossings.begin(), crossings.end());
      // Even-odd: [crossings[0], crossings[1]], [crossings[2], crossings[3]], ... are inside.
      std::size_t interval = 0;
      for (std::size_t k = 0; k < cells.size(); ++k) {
        const double left = origin_.x() + cells[k] * cell_size_;
        const double right = left + cell_size_;
        while (interval + 1 < crossings.size() && crossings[interval + 1] <= left) interval += 2;
        for (std::size_t j = interval; j + 1 < crossings.size() && crossings[j] < right; j += 2) {
          inside[k] +=
              std::max(0.0, std::min(right, crossings[j + 1]) - std::max(left, crossings[j]));
        }
      }
    }
    for (std::size_t k = 0; k < cells.size(); ++k) {
      fractions[index(row, cells[k])] =
          static_cast<float>(std::clamp(inside[k] / (kFractionLines * cell_size_), 0.0, 1.0));
    }
  }
  return fractions;
}

void CoverageRaster::appendConvexSpans(const Ring& convex, std::vector<CellSpan>& spans,
                                       int first_row, int end_row) const {
  if (convex.size() < 3) return;
  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  for (const Point2& p : convex) {
    low = std::min(low, p.y());
    high = std::max(high, p.y());
  }
  if (!std::isfinite(low) || !std::isfinite(high)) return;
  first_row = std::max(first_row, firstRowAtOrAbove(low));
  end_row = std::min(end_row, firstRowAtOrAbove(high));
  if (first_row >= end_row) return;
  // Each edge's crossings with the rows whose centres it spans (a.y <= y < b.y, tested
  // exactly on the rows around the estimate); a row's span runs from its leftmost to its
  // rightmost crossing. Linear in rows plus edges, not their product.
  const std::size_t count = static_cast<std::size_t>(end_row - first_row);
  thread_local std::vector<double> left;
  thread_local std::vector<double> right;
  left.assign(count, std::numeric_limits<double>::infinity());
  right.assign(count, -std::numeric_limits<double>::infinity());
  for (std::size_t i = 0, n = convex.size(); i < n; ++i) {
    const Point2& a = std::min(convex[i], convex[(i + 1) % n], lowerFirst);
    const Point2& b = std::max(convex[i], convex[(i + 1) % n], lowerFirst);
    if (a.y() == b.y()) continue;
    const int from = std::max(first_row, firstRowAtOrAbove(a.y()) - 1);
    const int to = std::min(end_row, firstRowAtOrAbove(b.y()) + 1);
    for (int row = from; row < to; ++row) {
      const double y = rowCentre(row);
      if ((a.y() <= y) == (b.y() <= y)) continue;
      const double x = crossingAt(a, b, y);
      const std::size_t k = static_cast<std::size_t>(row - first_row);
      left[k] = std::min(left[k], x);
      right[k] = std::max(right[k], x);
    }
  }
  for (int row = first_row; row < end_row; ++row) {
    const std::size_t k = static_cast<std::size_t>(row - first_row);
    if (!(left[k] < right[k])) continue;
    const int begin = firstColumnAtOrRightOf(left[k]);
    const int end = firstColumnAtOrRightOf(right[k]);
    if (begin < end) spans.push_back({row, begin, end});
  }
}

std::size_t CoverageRaster::countCells(const CellMask& mask) {
  return static_cast<std::size_t>(
      std::count_if(mask.begin(), mask.end(), [](std::uint8_t value) { return value != 0; }));
}

}  // namespace kinematic_coverage::core
