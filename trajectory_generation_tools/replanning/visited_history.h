#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "polygon_coverage_ros_bridge/sweeps/coverage_raster.h"
#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"

namespace kinematic_coverage::core {

/// The poses a robot visited, oldest first, in memory that does not grow with the length of
/// the mission (docs/REFERENCE.md, replanner). The newest kRecentPoses poses are kept as
/// they are; older ones are folded, kRecentPoses / 2 at a time, into what each replanning
/// method needs of them:
/// - `footprint`: their seen area (docs/REFERENCE.md, Sensor footprint and coverage) as one
///   bit per cell of a world-aligned raster of sweep spacing / 64 cells (the remaining
///   area's own resolution), kept in tiles of 64 x 64 cells that exist only where a
///   footprint reached: memory grows with the area seen, not with the time spent;
/// - `convex_hull`: the convex hull of their footprint corners, each corner snapped to the
///   nearest node of that raster (at most half a cell diagonal away), so that the hull has
///   few vertices however long the robot circles;
/// - `concave_hull`: their footprint corners thinned to the first one in each cell of a
///   sweep spacing / 16 grid, so the alpha shape sees the same outline.
/// A history of at most kRecentPoses poses therefore replans exactly as its poses would;
/// a longer one within one raster cell of that.
class VisitedHistory {
 public:
  /// Poses kept as they are.
  static constexpr std::size_t kRecentPoses = 4096;

  /// An empty history whose footprints are `sensor`'s.
  explicit VisitedHistory(const FrustumSensor& sensor);

  /// Throws InvalidInputError, naming the pose `name`, for a non-finite coordinate or
  /// heading, or a coordinate beyond the size limit (kMaxCoordinateMagnitude).
  static void check(const Pose2& pose, const std::string& name);

  /// Appends a pose. Throws InvalidInputError as check (nothing is added then).
  void add(const Pose2& pose);

  /// Forgets every pose.
  void clear();

  /// Poses added since construction or the last clear.
  std::size_t count() const { return count_; }
  bool empty() const { return count_ == 0; }

  /// The newest pose; the history must not be empty.
  const Pose2& last() const { return recent_.back(); }

  /// The newest poses, oldest first: all of them while count() <= kRecentPoses.
  const std::vector<Pose2>& recent() const { return recent_; }

  /// The sensor whose footprints the history records.
  const FrustumSensor& sensor() const { return sensor_; }

  /// Sets the cells of `seen` (a mask of `raster`) whose centres lie in a seen cell of
  /// the folded poses.
  void markFoldedSeen(const CoverageRaster& raster, CellMask& seen) const;

  /// The folded poses' convex hull vertices (snapped corners), counter-clockwise.
  const Ring& foldedHull() const { return folded_hull_; }

  /// The folded poses' thinned footprint corners, in the order they were kept.
  const std::vector<Point2>& foldedCorners() const { return folded_corners_; }

  /// Tiles of the folded seen raster allocated so far (each 512 bytes).
  std::size_t tileCount() const { return tiles_.size(); }

 private:
  /// Cells per tile edge of the seen raster.
  static constexpr int kTileCells = 64;
  using Tile = std::vector<std::uint64_t>;  ///< kTileCells rows of kTileCells bits
  /// A (row, column) of a grid.
  using GridKey = std::pair<std::int64_t, std::int64_t>;
  struct GridKeyHash {
    std::size_t operator()(const GridKey& key) const {
      return std::hash<std::int64_t>()(key.first * 1000003 ^ key.second);
    }
  };

  /// Folds the oldest `count` recent poses (and each one's step to its successor).
  void fold(std::size_t count);
  /// Marks the cells of the world raster whose centres lie in the convex ring.
  void markConvex(const Ring& convex);
  /// Sets the cells [begin, end) of a row of the world raster.
  void setRun(std::int64_t row, std::int64_t begin, std::int64_t end);
  bool cellSet(std::int64_t row, std::int64_t column) const;

  FrustumSensor sensor_;
  double cell_size_;        ///< of the seen raster and the hull's snapping lattice
  double thinning_cell_m_;  ///< of the concave hull's corner grid
  std::size_t count_ = 0;
  std::vector<Pose2> recent_;
  std::unordered_map<GridKey, Tile, GridKeyHash> tiles_;
  Ring folded_hull_;
  std::vector<Point2> folded_corners_;
  std::unordered_set<GridKey, GridKeyHash> thinning_cells_;
};

}  // namespace kinematic_coverage::core
