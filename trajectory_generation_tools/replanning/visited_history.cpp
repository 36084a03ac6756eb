#include "trajectory_generation_tools/replanning/visited_history.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/sweeps/waypoint_path_poses.h"
#include "polygon_coverage_ros_bridge/validation/polygon_validator.h"

namespace kinematic_coverage::core {
namespace {

/// Raster cells per sweep spacing, as the remaining area's raster (remaining_area.cpp).
constexpr double kCellsPerSweepSpacing = 64.0;
/// Finest seen-raster cell, so that a cell index of any pose within the coordinate limit
/// fits 64 bits.
constexpr double kMinCellSize = 1e-3;
/// The concave hull's thinning grid, in seen-raster cells.
constexpr double kThinningCells = 4.0;

std::int64_t floorDivide(std::int64_t value, std::int64_t divisor) {
  const std::int64_t quotient = value / divisor;
  return quotient * divisor > value ? quotient - 1 : quotient;
}

std::int64_t gridIndex(double coordinate, double cell_size) {
  return static_cast<std::int64_t>(std::floor(coordinate / cell_size));
}

}  // namespace

VisitedHistory::VisitedHistory(const FrustumSensor& sensor)
    : sensor_(sensor),
      cell_size_(std::max(sensor_.sweepDistance() / kCellsPerSweepSpacing, kMinCellSize)),
      thinning_cell_m_(kThinningCells * cell_size_) {}

void VisitedHistory::check(const Pose2& pose, const std::string& name) {
  if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.yaw)) {
    throw InvalidInputError(name + " has a non-finite coordinate or heading");
  }
  if (std::abs(pose.x) > kMaxCoordinateMagnitude || std::abs(pose.y) > kMaxCoordinateMagnitude) {
    std::ostringstream message;
    message << name << " (" << pose.x << ", " << pose.y << ") lies beyond the coordinate limit of "
            << kMaxCoordinateMagnitude << " m";
    throw InvalidInputError(message.str());
  }
}

void VisitedHistory::add(const Pose2& pose) {
  check(pose, "a visited pose");
  recent_.push_back(pose);
  ++count_;
  if (recent_.size() > kRecentPoses) fold(kRecentPoses / 2);
}

void VisitedHistory::clear() {
  count_ = 0;
  recent_.clear();
  tiles_.clear();
  folded_hull_.clear();
  folded_corners_.clear();
  thinning_cells_.clear();
}

void VisitedHistory::fold(std::size_t count) {
  std::vector<Point2> hull_points(folded_hull_.begin(), folded_hull_.end());
  for (std::size_t i = 0; i < count; ++i) {
    const Ring previous = sensor_.footprint(recent_[i]);
    const Ring current = sensor_.footprint(recent_[i + 1]);
    // The step to the successor, as SeenArea sees it.
    if ((recent_[i + 1].position() - recent_[i].position()).norm() > kSamePositionTolerance) {
      std::vector<Point2> both(previous.begin(), previous.end());
      both.insert(both.end(), current.begin(), current.end());
      markConvex(convexHull(std::move(both)));
    } else {
      markConvex(previous);
      markConvex(current);
    }
    for (const Point2& corner : previous) {
      hull_points.emplace_back(std::round(corner.x() / cell_size_) * cell_size_,
                               std::round(corner.y() / cell_size_) * cell_size_);
      const GridKey cell{gridIndex(corner.y(), thinning_cell_m_),
                         gridIndex(corner.x(), thinning_cell_m_)};
      if (thinning_cells_.insert(cell).second) folded_corners_.push_back(corner);
    }
  }
  folded_hull_ = convexHull(std::move(hull_points));
  recent_.erase(recent_.begin(), recent_.begin() + static_cast<std::ptrdiff_t>(count));
}

void VisitedHistory::markConvex(const Ring& convex) {
  double min_x = convex.front().x(), max_x = min_x;
  double min_y = convex.front().y(), max_y = min_y;
  for (const Point2& p : convex) {
    min_x = std::min(min_x, p.x());
    max_x = std::max(max_x, p.x());
    min_y = std::min(min_y, p.y());
    max_y = std::max(max_y, p.y());
  }
  const std::int64_t column0 = gridIndex(min_x, cell_size_);
  const std::int64_t row0 = gridIndex(min_y, cell_size_);
  const int columns = static_cast<int>(gridIndex(max_x, cell_size_) - column0 + 1);
  const int rows = static_cast<int>(gridIndex(max_y, cell_size_) - row0 + 1);
  const CoverageRaster window(
      Point2(static_cast<double>(column0) * cell_size_, static_cast<double>(row0) * cell_size_),
      cell_size_, columns, rows);
  std::vector<CellSpan> spans;
  window.appendConvexSpans(convex, spans);
  for (const CellSpan& span : spans) {
    setRun(row0 + span.row, column0 + span.begin, column0 + span.end);
  }
}

void VisitedHistory::setRun(std::int64_t row, std::int64_t begin, std::int64_t end) {
  const std::int64_t tile_row = floorDivide(row, kTileCells);
  const std::int64_t local_row = row - tile_row * kTileCells;
  while (begin < end) {
    const std::int64_t tile_column = floorDivide(begin, kTileCells);
    const std::int64_t first = begin - tile_column * kTileCells;
    const std::int64_t last = std::min<std::int64_t>(kTileCells, end - tile_column * kTileCells);
    Tile& tile = tiles_[{tile_row, tile_column}];
    if (tile.empty()) tile.assign(kTileCells, 0);
    const std::uint64_t run =
        last - first == kTileCells ? ~std::uint64_t{0} : (std::uint64_t{1} << (last - first)) - 1;
    tile[local_row] |= run << first;
    begin = tile_column * kTileCells + last;
  }
}

bool VisitedHistory::cellSet(std::int64_t row, std::int64_t column) const {
  const GridKey key{floorDivide(row, kTileCells), floorDivide(column, kTileCells)};
  const auto tile = tiles_.find(key);
  if (tile == tiles_.end()) return false;
  return (tile->second[row - key.first * kTileCells] >> (column - key.second * kTileCells) & 1u) !=
         0;
}

void VisitedHistory::markFoldedSeen(const CoverageRaster& raster, CellMask& seen) const {
  if (tiles_.empty()) return;
  for (int row = 0; row < raster.rows(); ++row) {
    const double y = raster.origin().y() + (row + 0.5) * raster.cellSize();
    const std::int64_t world_row = gridIndex(y, cell_size_);
    for (int column = 0; column < raster.columns(); ++column) {
      const double x = raster.origin().x() + (column + 0.5) * raster.cellSize();
      if (cellSet(world_row, gridIndex(x, cell_size_))) seen[raster.index(row, column)] = 1;
    }
  }
}

}  // namespace kinematic_coverage::core
