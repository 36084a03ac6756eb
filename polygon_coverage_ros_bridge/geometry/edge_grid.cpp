#include "polygon_coverage_ros_bridge/geometry/edge_grid.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace kinematic_coverage::core {
namespace {

/// The smallest side of the grid's rectangle (m), so that edges along one line still get
/// cells of positive size.
constexpr double kMinExtent = 1e-9;

}  // namespace

EdgeGrid::EdgeGrid(const std::vector<Point2>& starts, const std::vector<Point2>& ends,
                   const Layout& layout) {
  const int edge_count = static_cast<int>(starts.size());
  if (edge_count == 0) return;
  Point2 low = starts.front();
  Point2 high = low;
  for (int e = 0; e < edge_count; ++e) {
    low = low.cwiseMin(starts[e]).cwiseMin(ends[e]);
    high = high.cwiseMax(starts[e]).cwiseMax(ends[e]);
  }
  const Point2 margin = Point2::Constant(layout.margin);
  origin_ = low - margin;
  size_ = (high - low + 2.0 * margin).cwiseMax(Point2::Constant(kMinExtent));
  const double cells = layout.cells_per_edge * static_cast<double>(edge_count);
  const double side = std::sqrt(size_.x() * size_.y() / cells);
  columns_ =
      std::clamp(static_cast<int>(std::ceil(size_.x() / side)), 1, layout.max_cells_per_axis);
  rows_ = std::clamp(static_cast<int>(std::ceil(size_.y() / side)), 1, layout.max_cells_per_axis);
  cell_width_ = size_.x() / columns_;
  cell_height_ = size_.y() / rows_;
  inverse_cell_width_ = 1.0 / cell_width_;
  inverse_cell_height_ = 1.0 / cell_height_;

  // Each edge goes into every cell its box, grown by the padding, overlaps: counted, then
  // filled in edge order, so every cell lists its edges ascending.
  std::vector<int> counts(static_cast<std::size_t>(columns_) * rows_ + 1, 0);
  auto forEachCell = [&](int e, auto&& use) {
    const Point2 padding = Point2::Constant(layout.padding);
    const Point2 box_low = starts[e].cwiseMin(ends[e]) - padding;
    const Point2 box_high = starts[e].cwiseMax(ends[e]) + padding;
    for (int r = row(box_low.y()); r <= row(box_high.y()); ++r) {
      for (int c = column(box_low.x()); c <= column(box_high.x()); ++c) use(r * columns_ + c);
    }
  };
  for (int e = 0; e < edge_count; ++e) forEachCell(e, [&](int cell) { ++counts[cell + 1]; });
  std::partial_sum(counts.begin(), counts.end(), counts.begin());
  cell_begin_ = counts;
  cell_edges_.assign(counts.back(), 0);
  for (int e = 0; e < edge_count; ++e) {
    forEachCell(e, [&](int cell) { cell_edges_[counts[cell]++] = e; });
  }
}

bool EdgeGrid::covers(const Point2& p) const {
  return columns_ > 0 && p.x() >= origin_.x() && p.y() >= origin_.y() &&
         p.x() <= origin_.x() + size_.x() && p.y() <= origin_.y() + size_.y();
}

EdgeGrid::CellRange EdgeGrid::cellsOf(const Point2& low, const Point2& high) const {
  if (columns_ == 0 ||
      !(high.x() >= origin_.x() && high.y() >= origin_.y() && low.x() <= origin_.x() + size_.x() &&
        low.y() <= origin_.y() + size_.y())) {
    return {0, 0, -1, -1};
  }
  return {column(low.x()), row(low.y()), column(high.x()), row(high.y())};
}

void EdgeGrid::collect(const CellRange& range, std::vector<int>* ids) const {
  ids->clear();
  if (range.empty()) return;
  for (int y = range.y0; y <= range.y1; ++y) {
    ids->insert(ids->end(), cellBegin(range.x0, y), cellEnd(range.x1, y));
  }
  std::sort(ids->begin(), ids->end());
  ids->erase(std::unique(ids->begin(), ids->end()), ids->end());
}

}  // namespace kinematic_coverage::core
