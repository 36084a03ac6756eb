#pragma once

#include <cstdint>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// The nearest of many straight segments to a point, for queries that would otherwise
/// scan every segment: the tracking error's distance to the desired path, the repair's
/// nearest point of a boundary of thousands of vertices. The segments are bucketed in a
/// uniform grid, so that a query near them looks at a few. Immutable after construction.
class NearestSegmentIndex {
 public:
  /// Most grid cells along the longer side of the segments' bounding box.
  static constexpr int kMaxCellsPerSide = 1024;

  /// The nearest segment: its distance and index.
  struct Nearest {
    double distance;
    std::uint32_t segment;
  };

  /// Segment i runs from starts[i] to ends[i] (finite coordinates; a segment may be a
  /// point). Throws InvalidInputError for no segments or a non-finite coordinate.
  NearestSegmentIndex(std::vector<Point2> starts, std::vector<Point2> ends);

  /// The nearest segment to `point` (exact, for any point, near the segments or far from
  /// them); among equally near ones, the lowest index, as a scan in index order finds it.
  Nearest nearest(const Point2& point) const;

  const Point2& start(std::uint32_t segment) const { return starts_[segment]; }
  const Point2& end(std::uint32_t segment) const { return ends_[segment]; }

 private:
  /// The grid cell of a point clamped into the grid.
  std::pair<int, int> cellOf(const Point2& point) const;
  /// `best`, or the nearest segment bucketed in cell (column, row) if nearer.
  Nearest nearestInCell(int column, int row, const Point2& point, Nearest best) const;

  std::vector<Point2> starts_;
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
