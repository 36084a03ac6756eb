#include "polygon_coverage_ros_bridge/geometry/nearest_segment_index.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {

NearestSegmentIndex::NearestSegmentIndex(std::vector<Point2> starts, std::vector<Point2> ends)
    : starts_(std::move(starts)), ends_(std::move(ends)) {
  if (starts_.empty() || starts_.size() != ends_.size()) {
    throw InvalidInputError("nearest segment index: no segments, or ends unmatched");
  }
  Point2 min = starts_.front();
  Point2 max = starts_.front();
  double length = 0.0;
  for (std::size_t s = 0; s < starts_.size(); ++s) {
    for (const Point2& p : {starts_[s], ends_[s]}) {
      if (!std::isfinite(p.x()) || !std::isfinite(p.y())) {
        throw InvalidInputError("nearest segment index: segment " + std::to_string(s) +
                                " is not finite");
      }
      min = min.cwiseMin(p);
      max = max.cwiseMax(p);
    }
    length += (ends_[s] - starts_[s]).norm();
  }

  // Cells about as long as the average segment, but no more than kMaxCellsPerSide along the
  // longer side: a query then looks at a few segments and the grid stays small.
  const Point2 extent = max - min;
  const double longer_side = extent.maxCoeff();
  cell_size_ = std::max(
      {length / static_cast<double>(starts_.size()), longer_side / kMaxCellsPerSide, 1e-9});
  origin_ = min;
  columns_ = std::min(kMaxCellsPerSide, static_cast<int>(extent.x() / cell_size_) + 1);
  rows_ = std::min(kMaxCellsPerSide, static_cast<int>(extent.y() / cell_size_) + 1);

  // Each segment, cut into pieces no longer than a cell, goes into the cells of each
  // piece's bounding box (at most 2 x 2), so that every cell a segment crosses lists it.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> cell_segment;
  for (std::size_t s = 0; s < starts_.size(); ++s) {
    const Point2 delta = ends_[s] - starts_[s];
    const std::size_t pieces =
        std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(delta.norm() / cell_size_)));
    for (std::size_t piece = 0; piece < pieces; ++piece) {
      const Point2 a = starts_[s] + delta * (static_cast<double>(piece) / pieces);
      const Point2 b = starts_[s] + delta * (static_cast<double>(piece + 1) / pieces);
      const auto [column_a, row_a] = cellOf(a);
      const auto [column_b, row_b] = cellOf(b);
      for (int row = std::min(row_a, row_b); row <= std::max(row_a, row_b); ++row) {
        for (int column = std::min(column_a, column_b); column <= std::max(column_a, column_b);
             ++column) {
          cell_segment.emplace_back(static_cast<std::uint32_t>(row * columns_ + column),
                                    static_cast<std::uint32_t>(s));
        }
      }
    }
  }
  std::sort(cell_segment.begin(), cell_segment.end());
  cell_segment.erase(std::unique(cell_segment.begin(), cell_segment.end()), cell_segment.end());
  cell_begin_.assign(static_cast<std::size_t>(columns_) * rows_ + 1, 0);
  for (const auto& entry : cell_segment) ++cell_begin_[entry.first + 1];
  for (std::size_t c = 1; c < cell_begin_.size(); ++c) cell_begin_[c] += cell_begin_[c - 1];
  cell_entries_.reserve(cell_segment.size());
  for (const auto& entry : cell_segment) cell_entries_.push_back(entry.second);
}

std::pair<int, int> NearestSegmentIndex::cellOf(const Point2& point) const {
  const auto index = [&](double offset, int count) {
    const double cell = std::floor(offset / cell_size_);
    return static_cast<int>(std::clamp(cell, 0.0, static_cast<double>(count - 1)));
  };
  return {index(point.x() - origin_.x(), columns_), index(point.y() - origin_.y(), rows_)};
}

NearestSegmentIndex::Nearest NearestSegmentIndex::nearestInCell(int column, int row,
                                                                const Point2& point,
                                                                Nearest best) const {
  const std::size_t cell = static_cast<std::size_t>(row) * columns_ + column;
  for (std::uint32_t e = cell_begin_[cell]; e < cell_begin_[cell + 1]; ++e) {
    const std::uint32_t s = cell_entries_[e];
    const double distance = distanceToSegment(point, starts_[s], ends_[s]);
    if (distance < best.distance || (distance == best.distance && s < best.segment)) {
      best = {distance, s};
    }
  }
  return best;
}

NearestSegmentIndex::Nearest NearestSegmentIndex::nearest(const Point2& point) const {
  // Rings of cells around the point's (clamped) cell. Every cell beyond ring k lies at
  // least k cells away from the clamped point, and clamping into the grid brings a point
  // no farther from any cell, so once the best distance is below k cells it is final
  // (strictly below: an equally near segment of a lower index may lie farther out).
  const auto [centre_column, centre_row] = cellOf(point);
  Nearest best{std::numeric_limits<double>::infinity(), 0};
  for (int k = 0;; ++k) {
    const int left = centre_column - k;
    const int right = centre_column + k;
    const int bottom = centre_row - k;
    const int top = centre_row + k;
    for (int row = std::max(bottom, 0); row <= std::min(top, rows_ - 1); ++row) {
      if (row == bottom || row == top) {
        for (int column = std::max(left, 0); column <= std::min(right, columns_ - 1); ++column) {
          best = nearestInCell(column, row, point, best);
        }
      } else {
        if (left >= 0) best = nearestInCell(left, row, point, best);
        if (right < columns_) best = nearestInCell(right, row, point, best);
      }
    }
    if (best.distance < k * cell_size_) return best;
    if (left <= 0 && bottom <= 0 && right >= columns_ - 1 && top >= rows_ - 1) return best;
  }
}

}  // namespace kinematic_coverage::core
