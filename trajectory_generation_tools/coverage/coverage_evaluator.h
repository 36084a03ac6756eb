#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "polygon_coverage_ros_bridge/sweeps/coverage_raster.h"
#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"
#include "polygon_coverage_ros_bridge/sweeps/seen_area.h"
#include "polygon_coverage_ros_bridge/sweeps/waypoint_path_poses.h"

namespace kinematic_coverage::core {

/// The coverage figures of one trajectory (docs/REFERENCE.md, Sensor footprint and coverage).
struct CoverageReport {
  /// Seen share of the free area, percent.
  double coverage_percent = 0.0;
  /// 100 - coverage_percent: the share of the free area never seen (thesis's "coverage loss").
  double coverage_loss_percent = 0.0;
  /// Seen share of the reachable area, percent ("covers X %" in requirements).
  double reachable_coverage_percent = 0.0;
  /// The reachable area never seen, square metres.
  double unseen_reachable_area_m2 = 0.0;
  /// The free area out of every footprint's reach (farther than half a footprint length
  /// from the offset free area), square metres.
  double unreachable_area_m2 = 0.0;
};

/// What one trajectory fails to see of what another sees, e.g. a smoothed trajectory of
/// its unsmoothed one: the price of smoothing in search area, reachable or not.
struct LostArea {
  /// Square metres of the free area the other sees and this one does not.
  double area_m2 = 0.0;
  /// The part of it in the reachable area, square metres.
  double reachable_area_m2 = 0.0;
  /// area_m2 as a share of the free area, percent.
  double percent_of_free_area = 0.0;
};

/// Cell edge (metres) of the rasters on which coverage_tool measures coverage: cells of
/// at most 5 cm, accurate to 0.1 % of the free area.
constexpr double kReportingCellSize = 0.05;

/// Angle (radians) between the reporting raster's axes and the map's: a boundary or a
/// lane along the grid would put all of its cells' centre samples on one side of it, a
/// bias of up to half a cell along its whole length (0.2 % of a 150 m^2 spiral of
/// corridors); at an angle no map drawn in whole degrees has, the samples fall on both
/// sides alike.
constexpr double kReportingGridAngle = 0.2;

/// Grids of up to this many cells are affordable for every report: maps smaller than
/// 50 m x 50 m get cells finer than kReportingCellSize, down to this count.
constexpr std::size_t kReportingFloorCells = 1'000'000;

/// The resolution of the coverage figures that coverage_tool reports: the automatic cell
/// size for a worst-case error of 0.1 % of the free area, but no finer than
/// kReportingCellSize on maps larger than 50 m x 50 m, nor than a grid of
/// kReportingFloorCells cells on smaller ones (a 30 m lake gets 3.2 cm cells, a 9 m comb
/// 0.9 cm). The worst case (perimeter * cell / 2) is looser than the typical error
/// (test/coverage/analytic_coverage_test.cpp); larger maps get the coarser cells that
/// the bound allows, which the 4 000 000-cell budget coarsens further on large maps (by
/// 1 % on a square, more on long or ragged maps, whose worst case then exceeds 0.1 %).
RasterResolution reportingResolution();

/// A connected piece of the reachable area that a trajectory never saw (cells touching at
/// an edge or a corner), in the map's frame: where the object could hide.
struct UnseenRegion {
  double area_m2 = 0.0;
  Point2 centroid = Point2::Zero();
  /// Its bounding box along the map's axes (4 corners, counter-clockwise), for plots.
  Ring outline;
  /// Centres of its cells spread evenly over it (map frame), as many as asked of
  /// CoverageEvaluator::unseenRegions: where a repair must look.
  std::vector<Point2> samples;
};

/// Evaluates what a sensor sees of a map: rasterizes the free area, the offset free area
/// and the reachable area once, then measures trajectories or waypoint paths on them.
class CoverageEvaluator {
 public:
  /// Prepares the masks on a raster chosen for the free area at `resolution`;
  /// `offset_parts` are the parts of the offset free area (one, or several where the
  /// wall offset splits the free area), every one of them grown into the reachable area.
  /// Throws InvalidInputError for degenerate or non-finite areas, a sensor whose width is
  /// not > 0 or whose length is not >= 0, or an offset free area that covers no cell.
  /// With `grid_angle`, the raster's axes turn by that angle against the map's (the map,
  /// the areas and every pose are turned by its opposite before they are rasterized);
  /// raster(), the masks and the seen areas are then in the raster's frame.
  CoverageEvaluator(const PolygonWithHoles& free_area,
                    const std::vector<PolygonWithHoles>& offset_parts, const FrustumSensor& sensor,
                    const RasterResolution& resolution = {}, double grid_angle = 0.0);

  const CoverageRaster& raster() const { return raster_; }
  const CellMask& freeArea() const { return free_area_; }
  const CellMask& offsetFreeArea() const { return offset_free_area_; }
  const CellMask& reachableArea() const { return reachable_area_; }

  /// The seen area of a sampled trajectory (docs/REFERENCE.md, Sensor footprint and coverage).
  SeenArea seeTrajectory(const std::vector<Pose2>& poses) const;

  /// What the sensor sees along a waypoint path driven as straight legs with in-place
  /// rotations between them (see SeenArea::addWaypointPath).
  SeenArea seeWaypointPath(const std::vector<Pose2>& waypoints,
                           double rotation_step = kDefaultRotationStep) const;

  /// The coverage figures of a seen area made on this evaluator's raster: coverage_percent
  /// weighs every seen cell by its share inside the free area (areaFractions), the
  /// reachable figures count the cells whose centres lie in the reachable area.
  CoverageReport report(const SeenArea& seen) const;

  /// The area `reference` sees and `seen` does not, both made on this evaluator's raster:
  /// every such cell weighed by its share inside the free area, the reachable part counted
  /// by the cells whose centres lie in the reachable area (as report() counts them).
  LostArea lostArea(const SeenArea& reference, const SeenArea& seen) const;

  /// Keeps of the reachable area only the cells whose centres lie in `region` (map frame):
  /// where a replanned path must see, the remaining area of a mission, not what the robot
  /// has already seen.
  void restrictReachableArea(const std::vector<PolygonWithHoles>& region);

  /// The index of the raster cell that holds p (map frame), if any.
  std::optional<std::size_t> cellAt(const Point2& p) const;

  /// The visits of a seen area made on this evaluator's raster, read at the cell centres
  /// of `grid` (map frame; each from the raster cell that holds it, 0 outside the raster):
  /// the heatmap on another grid, such as a plot's along the map's axes, without seeing the
  /// poses again.
  Heatmap heatmapOn(const SeenArea& seen, const CoverageRaster& grid) const;

  /// The largest UnseenRegion of a seen area made on this evaluator's raster; none when
  /// the whole reachable area was seen.
  std::optional<UnseenRegion> largestUnseenRegion(const SeenArea& seen) const;

  /// Every UnseenRegion of a seen area made on this evaluator's raster, the largest first,
  /// each with up to `samples_per_region` of its cells' centres (every k-th cell of its
  /// flood fill, so that they spread over it). Cells within `join_distance` (m) of each
  /// other belong to one region: a ragged sliver along a wall is one region, not hundreds.
  std::vector<UnseenRegion> unseenRegions(const SeenArea& seen, std::size_t samples_per_region,
                                          double join_distance = 0.0) const;

 private:
  /// Map frame to raster frame, and back.
  Point2 toRaster(const Point2& p) const;
  Point2 fromRaster(const Point2& p) const;
  /// The reachable cells `seen` never saw, ascending; with a join distance > 0, `joined`
  /// gets them grown by half of it (the cells through which unseen cells connect), else it
  /// stays empty.
  std::vector<std::size_t> unseenCells(const SeenArea& seen, double join_distance,
                                       CellMask* joined) const;
  /// True when cell `i` is reachable and `seen` never saw it.
  bool unseenAt(const SeenArea& seen, std::size_t i) const {
    return reachable_area_[i] != 0 && !seen.seen(i);
  }
  /// Throws InvalidInputError unless `seen` was made on this evaluator's raster.
  void requireOwnRaster(const SeenArea& seen) const;
  std::vector<Pose2> toRaster(const std::vector<Pose2>& poses) const;
  /// The free-area shares, computed at the first call.
  const CellFractions& freeFractions() const;

  FrustumSensor sensor_;
  double grid_angle_;
  Eigen::Matrix2d to_raster_;    ///< turns the map frame by -grid_angle_
  Eigen::Matrix2d from_raster_;  ///< and back
  /// The free area in the raster's frame, and each cell's share inside it (the weight of
  /// coverage_percent): computed when first needed (a planner's measuring raster never
  /// reports) and shared by copies.
  struct FreeFractions;
  std::shared_ptr<FreeFractions> free_fractions_;
  CoverageRaster raster_;
  CellMask free_area_;
  CellMask offset_free_area_;
  CellMask reachable_area_;
};

/// Seen share of the reachable area, in percent, of the footprints swept along a waypoint
/// path (straight legs, in-place rotations swept in steps of `rotation_step`); the check of
/// the planner's tests that a plan "covers X %". Robust to duplicate waypoints and
/// zero-length legs. Throws InvalidInputError as CoverageEvaluator and waypointPathPoses do.
double waypointPathReachableCoveragePercent(const PolygonWithHoles& free_area,
                                            const std::vector<PolygonWithHoles>& offset_parts,
                                            const FrustumSensor& sensor,
                                            const std::vector<Pose2>& waypoints,
                                            const RasterResolution& resolution = {},
                                            double rotation_step = kDefaultRotationStep);

}  // namespace kinematic_coverage::core
