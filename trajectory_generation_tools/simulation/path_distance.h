#pragma once

#include <cstdint>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// The distance from a point to a polyline, for the tracking error of a simulated robot:
/// the distance from the robot to the nearest point of the desired path (docs/REFERENCE.md,
/// Metrics: `tracking_error_sum_m`). The polyline's segments are bucketed in a uniform
/// grid, so that a query near the path looks at a few segments however long the path is.
class PathDistance {
 public:
  /// Most grid cells along the longer side of the polyline's bounding box.
  static constexpr int kMaxCellsPerSide = 1024;

  /// Indexes the polyline through `points` (consecutive equal points allowed; one point is
  /// a path of that point). Throws InvalidInputError for no points or a non-finite one.
  explicit PathDistance(const std::vector<Point2>& points);

  /// The distance from `point` to the nearest point of the polyline (exact, for any point,
  /// near the path or far from it).
  double distance(const Point2& point) const;

  /// The nearest point of the polyline to `point` (the first found among equally near ones).
  Point2 nearestPoint(const Point2& point) const;

 private:
  /// The grid cell of a point clamped into the grid.
  std::pair<int, int> cellOf(const Point2& point) const;
  /// The nearest segment found so far: its distance and index.
  struct Nearest {
    double distance;
    std::uint32_t segment;
  };
  /// `best`, or the nearest segment bucketed in cell (column, row) if nearer.
  Nearest nearestInCell(int column, int row, const Point2& point, Nearest best) const;
  /// The nearest segment to `point`.
  Nearest nearestSegment(const Point2& point) const;

  std::vector<Point2> starts_;  ///< segment i runs from starts_[i] to ends_[i]
  std::vector<Point2> ends_;
  Point2 origin_ = Point2::Zero();
  double cell_size_ = 1.0;
  int columns_ = 1;
  int rows_ = 1;
  /// Segments of cell c: cell_entries_[cell_begin_[c] .. cell_begin_[c + 1]), where
  /// c = row * columns_ + column.
  std::vector<std::uint32_t> cell_begin_;
  std::vector<std::uint32_t> cell_entries_;
};

}  // namespace kinematic_coverage::core
