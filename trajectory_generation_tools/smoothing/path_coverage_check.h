#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "polygon_coverage_ros_bridge/sweeps/coverage_raster.h"
#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"
#include "polygon_coverage_ros_bridge/sweeps/seen_area.h"
#include "trajectory_generation_tools/path/path_primitive.h"
#include "trajectory_generation_tools/smoothing/smoothing_strategy.h"

namespace kinematic_coverage::core {

/// The stretch of the sharp path that one smoothing replaces: from where its first arc
/// leaves the path, through the corners it cuts, to where its last arc rejoins the path.
using ReplacedStretch = std::vector<Point2>;

/// The test behind coverage-safe smoothing: the reachable area that a smoothed path fails
/// to see of what the sharp waypoint path it smooths sees, counted over the whole path, so
/// that a corner cut whose area another lane sees again loses nothing, while one whose
/// area nothing else sees (the far end of a dead-end bay swept up and back) does. Both
/// paths are measured alike (SeenArea::addWaypointPath and addSweptPath) on one raster of
/// cells a small fraction of the footprint. The reachable area is the coverage report's
/// (docs/REFERENCE.md, Metrics): the free cells within half a footprint length of the offset
/// free area's polygons (the offset free area itself for a line sensor), its rim measured
/// against the polygons as the report measures it, so that the losses at lane ends along a
/// wall, where the rim runs, count as the report counts them.
class PathCoverageCheck {
 public:
  /// Cells of the raster per footprint length (or width, if shorter; the width for a line
  /// sensor), finer while the raster has fewer than kFloorCells cells (a small map, where
  /// each corner's tolerated cells would be a large share of it), coarsened to at most
  /// kMaxCells over the path.
  static constexpr double kCellsPerFootprint = 16.0;
  static constexpr std::size_t kFloorCells = 250'000;
  static constexpr std::size_t kMaxCells = 2'000'000;

  /// Measures what the sharp path through `waypoints` (straight legs, in-place rotations)
  /// sees of the reachable area of `free_area` (an empty hull: the unbounded plane, all of
  /// it reachable) with walls kept `wall_distance` away: the free cells whose centres lie
  /// within half a footprint length of `exact_parts`, the exact offset free area's polygons
  /// (exactOffsetParts; empty: those of the whole offset free area), measured as the
  /// coverage report measures them. With
  /// `guarded` kFree every free cell counts as reachable does below: the check then keeps
  /// all that the sharp path sees. Throws InvalidInputError for a non-finite coordinate or
  /// a negative or non-finite wall distance.
  PathCoverageCheck(const PolygonWithHoles& free_area, double wall_distance,
                    const std::vector<PolygonWithHoles>& exact_parts, const FrustumSensor& sensor,
                    const std::vector<Point2>& waypoints,
                    CoverageSafeArea guarded = CoverageSafeArea::kReachable);

  /// Per stretch, the reachable cells within the sensor's reach of it (half the
  /// footprint's diagonal) that the sharp path sees and the path of `primitives`
  /// (segments, arcs, rotations) does not. A stretch whose neighbourhood (the stretch and
  /// every primitive that can see near it) is as in an earlier call keeps that call's count;
  /// only the others are measured, from the primitives near them, so that the rounds of
  /// coverage-safe smoothing, which change a few corners each, cost what they change.
  std::vector<std::size_t> lostCells(const std::vector<PathPrimitive>& primitives,
                                     const std::vector<ReplacedStretch>& stretches);

  /// The reachable cells within the sensor's reach of `stretch` that the sharp path sees
  /// and would no longer see if its legs `first_leg` to `last_leg` (and the in-place
  /// rotations between them) were driven as `replacement` instead, the rest of the path
  /// staying sharp: the test of one guarded corner's smoothing (`replacement` runs from
  /// the first leg's start to the last leg's end). Cheap: measured on a window of the
  /// raster around the stretch, from the sharp primitives that can see into it.
  std::size_t lostCellsReplacing(std::size_t first_leg, std::size_t last_leg,
                                 const std::vector<PathPrimitive>& replacement,
                                 const ReplacedStretch& stretch) const;

  /// Area (m^2) of one cell of the raster.
  double cellArea() const { return raster_ ? raster_->cellArea() : 0.0; }

  /// Share of the reachable area the sharp path sees that its smoothing may lose in all:
  /// the sharp and smoothed paths are sampled differently, and a corner cut by a few
  /// cells is not worth a sharp turn, but the losses of many corners add up.
  static constexpr double kToleratedLostShare = 2e-4;
  /// kToleratedLostShare of the reachable cells the sharp path sees.
  std::size_t toleratedLostCells() const { return tolerated_lost_cells_; }

 private:
  FrustumSensor sensor_;
  double reach_ = 0.0;  ///< half the footprint's diagonal
  std::optional<CoverageRaster> raster_;
  CellMask reachable_;
  std::optional<SeenArea> sharp_;
  /// The sharp path as primitives: leg k from waypoint k to k + 1, and the in-place
  /// rotation at waypoint k (1 to legs - 1; none at a waypoint where the heading keeps).
  std::vector<PathPrimitive> legs_;
  std::vector<std::optional<PathPrimitive>> rotations_;
  std::size_t tolerated_lost_cells_ = 0;

  /// A stretch measured by an earlier call: its neighbourhood and its lost cells.
  struct MeasuredStretch {
    ReplacedStretch stretch;
    std::vector<PathPrimitive> nearby;
    std::size_t lost = 0;
  };
  std::vector<MeasuredStretch> measured_;
};

}  // namespace kinematic_coverage::core
