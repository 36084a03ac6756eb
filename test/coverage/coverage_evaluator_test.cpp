#include "trajectory_generation_tools/coverage/coverage_evaluator.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <thread>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"
#include "polygon_coverage_ros_bridge/sweeps/reachable_area.h"
#include "test/support/random_polygons.h"

namespace kinematic_coverage::core {
namespace {

/// The axis-parallel rectangle [x0, x1] x [y0, y1]; counter-clockwise, or clockwise for a hole.
Ring rectangle(double x0, double y0, double x1, double y1, bool clockwise = false) {
  Ring ring{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  if (clockwise) std::reverse(ring.begin(), ring.end());
  return ring;
}

/// Boustrophedon waypoints over [x0, x1] with lanes from y0 every `spacing` up to y1, and
/// a last lane at y1 itself.
std::vector<Pose2> lawnmower(double x0, double x1, double y0, double y1, double spacing) {
  std::vector<double> lanes;
  for (double y = y0; y < y1 - 1e-9; y += spacing) lanes.push_back(y);
  lanes.push_back(y1);
  std::vector<Pose2> waypoints;
  for (std::size_t k = 0; k < lanes.size(); ++k) {
    const bool forward = k % 2 == 0;
    waypoints.push_back({forward ? x0 : x1, lanes[k], 0.0});
    waypoints.push_back({forward ? x1 : x0, lanes[k], 0.0});
  }
  return waypoints;
}

// The largest unseen piece of the reachable area, found on a turned raster and reported
// in the map's frame: a lane along the bottom of a 40 m x 10 m area, a leg up its right
// end and a short one back leave x 0 to 35, y 4 to 10 and x 35 to 38, y 4 to 6 unseen,
// one region of 216 m^2.
TEST(CoverageEvaluator, NamesTheLargestUnseenRegionInTheMapsFrame) {
  const PolygonWithHoles area{rectangle(0, 0, 40, 10), {}};
  const FrustumSensor sensor(4.0, 2.0, 0.0);
  for (const double angle : {0.0, 0.2}) {
    SCOPED_TRACE("grid angle " + std::to_string(angle));
    const CoverageEvaluator evaluator(area, {area}, sensor, {0.05}, angle);
    const SeenArea seen =
        evaluator.seeWaypointPath({{0, 2, 0}, {40, 2, 0}, {40, 8, 0}, {36, 8, 0}});
    const std::optional<UnseenRegion> region = evaluator.largestUnseenRegion(seen);
    ASSERT_TRUE(region.has_value());
    EXPECT_NEAR(region->area_m2, 216.0, 2.0);
    EXPECT_NEAR(region->centroid.x(), (210.0 * 17.5 + 6.0 * 36.5) / 216.0, 0.2);
    EXPECT_NEAR(region->centroid.y(), (210.0 * 7.0 + 6.0 * 5.0) / 216.0, 0.2);
    ASSERT_EQ(region->outline.size(), 4u);
    EXPECT_NEAR(region->outline[0].x(), 0.0, 0.1);
    EXPECT_NEAR(region->outline[0].y(), 4.0, 0.1);
    EXPECT_NEAR(region->outline[2].x(), 38.0, 0.1);
    EXPECT_NEAR(region->outline[2].y(), 10.0, 0.1);
  }
  const CoverageEvaluator evaluator(area, {area}, sensor, {0.05});
  EXPECT_FALSE(evaluator.largestUnseenRegion(evaluator.seeWaypointPath(lawnmower(0, 40, 0, 10, 2)))
                   .has_value());
}

// cellAt finds the cell that holds a map point on a turned raster, and none off the grid.
TEST(CoverageEvaluator, CellAtHoldsThePointOnATurnedRaster) {
  const PolygonWithHoles area{rectangle(0, 0, 40, 10), {}};
  const CoverageEvaluator evaluator(area, {area}, FrustumSensor(4.0, 1.0, 0.0), {0.05}, 0.2);
  const double half_diagonal = std::sqrt(0.5) * evaluator.raster().cellSize();
  for (const Point2& p : {Point2(0.01, 0.01), Point2(17.3, 4.2), Point2(39.99, 9.99)}) {
    const std::optional<std::size_t> cell = evaluator.cellAt(p);
    ASSERT_TRUE(cell.has_value()) << p.transpose();
    const Point2 centre = Eigen::Rotation2Dd(0.2) * evaluator.raster().cellCentre(*cell);
    EXPECT_LE((centre - p).norm(), half_diagonal + 1e-12) << p.transpose();
  }
  EXPECT_FALSE(evaluator.cellAt({-100.0, 5.0}).has_value());
  EXPECT_FALSE(evaluator.cellAt({20.0, 100.0}).has_value());
}

// The heatmap on the map's axes is the turned raster's visits at each cell centre; on the
// evaluator's own grid it is the seen area's heatmap itself.
TEST(CoverageEvaluator, HeatmapOnAnotherGridReadsTheVisitsAtItsCellCentres) {
  const PolygonWithHoles area{rectangle(0, 0, 40, 10), {}};
  const std::vector<Pose2> lanes = lawnmower(1, 39, 1, 9, 1.5);
  const CoverageEvaluator turned(area, {area}, FrustumSensor(4.0, 1.0, 0.0), {0.05}, 0.2);
  const SeenArea seen = turned.seeWaypointPath(lanes);
  const CoverageRaster grid = CoverageRaster::covering(area, {0.1});
  const Heatmap heatmap = turned.heatmapOn(seen, grid);
  EXPECT_EQ(heatmap.columns, grid.columns());
  EXPECT_EQ(heatmap.rows, grid.rows());
  EXPECT_EQ(heatmap.cell_size, 0.1);
  ASSERT_EQ(heatmap.visits.size(), grid.cellCount());
  std::size_t overlapped = 0;
  for (std::size_t index = 0; index < grid.cellCount(); ++index) {
    const std::optional<std::size_t> cell = turned.cellAt(grid.cellCentre(index));
    EXPECT_EQ(heatmap.visits[index], cell ? seen.visits(*cell) : 0) << index;
    if (heatmap.visits[index] >= 2) ++overlapped;
  }
  EXPECT_GT(overlapped, 0u);  // lanes 1.5 m apart under a 4 m footprint overlap

  const CoverageEvaluator along_axes(area, {area}, FrustumSensor(4.0, 1.0, 0.0), {0.05}, 0.0);
  const SeenArea seen_along = along_axes.seeWaypointPath(lanes);
  EXPECT_EQ(along_axes.heatmapOn(seen_along, along_axes.raster()).visits,
            seen_along.heatmap().visits);
  EXPECT_THROW(along_axes.heatmapOn(seen, grid), InvalidInputError);
}

// Restricted to a region (a replanned mission's remaining area), the reachable area is its
// cells inside the region, on a turned raster too; what lies outside is neither reachable
// nor unseen.
TEST(CoverageEvaluator, ReachableAreaRestrictedToARegion) {
  const PolygonWithHoles area{rectangle(0, 0, 40, 10), {}};
  CoverageEvaluator evaluator(area, {area}, FrustumSensor(4.0, 0.0, 0.0), {0.05}, 0.2);
  const double cell_area = evaluator.raster().cellArea();
  EXPECT_NEAR(CoverageRaster::countCells(evaluator.reachableArea()) * cell_area, 400.0, 2.0);
  evaluator.restrictReachableArea({{rectangle(10, 0, 20, 10), {}}, {rectangle(30, 5, 35, 10), {}}});
  EXPECT_NEAR(CoverageRaster::countCells(evaluator.reachableArea()) * cell_area, 125.0, 1.0);
  // A lane along y = 2 sees y 0 to 4: of the region, 10 m x 4 m.
  const CoverageReport report =
      evaluator.report(evaluator.seeWaypointPath({{0, 2, 0}, {40, 2, 0}}));
  EXPECT_NEAR(report.unseen_reachable_area_m2, 85.0, 1.0);
  for (const UnseenRegion& region :
       evaluator.unseenRegions(evaluator.seeWaypointPath({{0, 2, 0}, {40, 2, 0}}), 20)) {
    for (const Point2& p : region.samples) {
      EXPECT_TRUE((p.x() > 10.0 - 0.05 && p.x() < 20.0 + 0.05) || p.x() > 30.0 - 0.05)
          << p.transpose();
    }
  }
}

// Every unseen region, the largest first, with samples spread over it: a lane along the
// middle of a 40 m x 10 m area (W 4 m, L 0) and one back along its right half 1 m lower
// leave a band above (40 m x 3 m) and one below (x 0 to 20 m 3 m high, x 20 to 40 m 2 m).
TEST(CoverageEvaluator, ListsEveryUnseenRegionLargestFirstWithSamplesInside) {
  const PolygonWithHoles area{rectangle(0, 0, 40, 10), {}};
  const FrustumSensor sensor(4.0, 0.0, 0.0);
  const CoverageEvaluator evaluator(area, {area}, sensor, {0.05}, 0.2);
  const SeenArea seen = evaluator.seeWaypointPath({{0, 5, 0}, {40, 5, 0}, {40, 4, 0}, {20, 4, 0}});
  const std::vector<UnseenRegion> regions = evaluator.unseenRegions(seen, 50);
  ASSERT_EQ(regions.size(), 2u);
  EXPECT_NEAR(regions[0].area_m2, 120.0, 1.0);
  EXPECT_NEAR(regions[1].area_m2, 100.0, 1.0);
  EXPECT_GT(regions[0].centroid.y(), 5.0);
  for (const UnseenRegion& region : regions) {
    EXPECT_LE(region.samples.size(), 50u);
    EXPECT_GE(region.samples.size(), 40u);
    for (const Point2& p : region.samples) {
      EXPECT_TRUE(p.y() > 7.0 - 0.05 || p.y() < 3.0 + 0.05) << p.transpose();
      EXPECT_EQ(p.y() > 5.0, region.centroid.y() > 5.0);
    }
  }
  EXPECT_TRUE(
      evaluator.unseenRegions(evaluator.seeWaypointPath(lawnmower(0, 40, 0, 10, 2)), 10).empty());
  // The bands lie 4 m apart where x < 20 (y 3 to 7 seen between them): joined within 4.5 m,
  // they are one region; within 3.5 m, still two.
  const std::vector<UnseenRegion> joined = evaluator.unseenRegions(seen, 50, 4.5);
  ASSERT_EQ(joined.size(), 1u);
  EXPECT_NEAR(joined[0].area_m2, 220.0, 2.0);
  EXPECT_LE(joined[0].samples.size(), 50u);
  EXPECT_EQ(evaluator.unseenRegions(seen, 50, 3.5).size(), 2u);
}

TEST(CoverageEvaluator, LawnmowerWithOverlapCoversTheReachableArea) {
  // 30 m square, 1 m wall distance, the thesis's 40 % overlap, footprint 4 m x 1.6 m.
  const PolygonWithHoles free_area{rectangle(0, 0, 30, 30), {}};
  const PolygonWithHoles offset_area{rectangle(1, 1, 29, 29), {}};
  const FrustumSensor sensor(4.0, 1.6, 0.4);
  const CoverageEvaluator evaluator(free_area, {offset_area}, sensor);
  const std::vector<Pose2> waypoints = lawnmower(1, 29, 1, 29, sensor.sweepDistance());
  const SeenArea seen = evaluator.seeWaypointPath(waypoints);
  const CoverageReport report = evaluator.report(seen);
  EXPECT_GE(report.reachable_coverage_percent, 99.9);
  // Only cells at the rim of the reachable area may be missed (raster rounding).
  for (const Point2& centre : seen.unseenCentres(evaluator.reachableArea(), 100000)) {
    const double to_rim = std::min({centre.x() - 0.2, 29.8 - centre.x()});
    EXPECT_LE(to_rim, evaluator.raster().cellSize()) << centre.transpose();
  }
  // The free area's side strips beyond the footprint's reach stay partly unseen.
  EXPECT_LT(report.coverage_percent, 100.0);
  EXPECT_GT(report.coverage_percent, 98.5);
  EXPECT_DOUBLE_EQ(report.coverage_loss_percent, 100.0 - report.coverage_percent);
  EXPECT_DOUBLE_EQ(
      waypointPathReachableCoveragePercent(free_area, {offset_area}, sensor, waypoints),
      report.reachable_coverage_percent);
}

TEST(CoverageEvaluator, LineSensorLawnmowerCoversTheOffsetArea) {
  const PolygonWithHoles free_area{rectangle(0, 0, 30, 30), {}};
  const PolygonWithHoles offset_area{rectangle(1, 1, 29, 29), {}};
  const FrustumSensor sensor(4.0, 0.0, 0.0);
  const double coverage = waypointPathReachableCoveragePercent(
      free_area, {offset_area}, sensor, lawnmower(1, 29, 1, 29, sensor.sweepDistance()));
  EXPECT_GE(coverage, 99.9);
  // Lanes twice as far apart leave every other strip unseen.
  const double sparse = waypointPathReachableCoveragePercent(
      free_area, {offset_area}, sensor, lawnmower(1, 29, 1, 29, 2.0 * sensor.sweepDistance()));
  EXPECT_LT(sparse, 80.0);
}

TEST(CoverageEvaluator, SquareWithHoleCountsOnlyTheFreeArea) {
  PolygonWithHoles free_area{rectangle(0, 0, 20, 20), {rectangle(8, 8, 12, 12, true)}};
  PolygonWithHoles offset_area{rectangle(1, 1, 19, 19), {rectangle(7, 7, 13, 13, true)}};
  const FrustumSensor sensor(2.0, 1.0, 0.0);
  const CoverageEvaluator evaluator(free_area, {offset_area}, sensor);
  EXPECT_NEAR(evaluator.raster().area(evaluator.freeArea()), 384.0, 0.384);
  // Sweeping just the hole's square sees nothing of the free area but the free shares of
  // the cells its 2 m sides cut, which the footprint's equal sides see (at most half a
  // cell along both).
  const CoverageReport hole_only =
      evaluator.report(evaluator.seeTrajectory({{8.5, 10.0, 0.0}, {11.5, 10.0, 0.0}}));
  EXPECT_NEAR(hole_only.coverage_percent, 0.0, 100.0 * 2.0 * evaluator.raster().cellSize() / 384.0);
  // Sweeping the lower 2 m strip sees 40 of 384 m^2.
  const CoverageReport strip =
      evaluator.report(evaluator.seeTrajectory({{0.5, 1.0, 0.0}, {19.5, 1.0, 0.0}}));
  EXPECT_NEAR(strip.coverage_percent, 100.0 * 40.0 / 384.0, 0.1);
}

// The free area's cell shares are computed at the first report: a copy made before it, and
// reports asked for on two threads at once, give what a fresh evaluator gives.
TEST(CoverageEvaluator, CopiesAndConcurrentReportsShareTheFreeShares) {
  const PolygonWithHoles free_area{rectangle(0, 0, 20, 20), {rectangle(8, 8, 12, 12, true)}};
  const PolygonWithHoles offset_area{rectangle(1, 1, 19, 19), {rectangle(7, 7, 13, 13, true)}};
  const FrustumSensor sensor(2.0, 1.0, 0.0);
  const std::vector<Pose2> strip = {{0.5, 1.0, 0.0}, {19.5, 1.0, 0.0}};
  const CoverageEvaluator fresh(free_area, {offset_area}, sensor, {}, 0.3);
  const CoverageReport expected = fresh.report(fresh.seeTrajectory(strip));
  const CoverageEvaluator original(free_area, {offset_area}, sensor, {}, 0.3);
  const CoverageEvaluator copy = original;
  const SeenArea seen = original.seeTrajectory(strip);
  CoverageReport first;
  CoverageReport second;
  std::thread other([&] { first = original.report(seen); });
  second = copy.report(seen);
  other.join();
  for (const CoverageReport& report : {first, second}) {
    EXPECT_EQ(report.coverage_percent, expected.coverage_percent);
    EXPECT_EQ(report.unreachable_area_m2, expected.unreachable_area_m2);
  }
  EXPECT_EQ(copy.lostArea(seen, copy.seeTrajectory({})).area_m2,
            fresh.lostArea(fresh.seeTrajectory(strip), fresh.seeTrajectory({})).area_m2);
}

TEST(CoverageEvaluator, DuplicateWaypointsAndZeroLengthLegsChangeNothing) {
  const PolygonWithHoles free_area{rectangle(0, 0, 30, 30), {}};
  const PolygonWithHoles offset_area{rectangle(1, 1, 29, 29), {}};
  const FrustumSensor sensor(4.0, 1.6, 0.4);
  const CoverageEvaluator evaluator(free_area, {offset_area}, sensor);
  const std::vector<Pose2> clean = lawnmower(1, 29, 1, 29, sensor.sweepDistance());
  std::vector<Pose2> repeated;
  for (const Pose2& waypoint : clean) {
    repeated.push_back(waypoint);
    repeated.push_back({waypoint.x, waypoint.y, waypoint.yaw + 1.0});
    repeated.push_back({waypoint.x + 1e-12, waypoint.y, waypoint.yaw});
  }
  const SeenArea from_clean = evaluator.seeWaypointPath(clean);
  const SeenArea from_repeated = evaluator.seeWaypointPath(repeated);
  EXPECT_EQ(from_clean.heatmap().visits, from_repeated.heatmap().visits);
  // A single waypoint, repeated: its footprint with its own yaw.
  const SeenArea still = evaluator.seeWaypointPath({{15, 15, 0.5}, {15, 15, 0.5}, {15, 15, 2.0}});
  EXPECT_NEAR(evaluator.raster().area(still.seenMask()), 4.0 * 1.6, 0.05);
  // No waypoint: nothing seen.
  EXPECT_DOUBLE_EQ(evaluator.report(evaluator.seeWaypointPath({})).coverage_percent, 0.0);
}

TEST(CoverageEvaluator, WaypointPathPosesTurnInPlaceTheShorterWay) {
  const std::vector<Pose2> poses =
      waypointPathPoses({{0, 0, 0}, {10, 0, 0}, {10, 0, 0}, {10, -5, 0}}, 0.2);
  // Leg heading 0, rotation to -pi/2 clockwise in ceil((pi/2) / 0.2) = 8 steps, leg.
  ASSERT_EQ(poses.size(), 2u + 8u + 1u);
  EXPECT_DOUBLE_EQ(poses[0].yaw, 0.0);
  EXPECT_DOUBLE_EQ(poses[1].yaw, 0.0);
  for (std::size_t k = 2; k < 10; ++k) {
    EXPECT_LT(poses[k].yaw, poses[k - 1].yaw);
    EXPECT_NEAR(poses[k - 1].yaw - poses[k].yaw, M_PI / 16, 1e-12);
  }
  EXPECT_NEAR(poses[9].yaw, -M_PI / 2, 1e-12);
  EXPECT_NEAR(poses[10].x, 10.0, 1e-12);
  EXPECT_NEAR(poses[10].y, -5.0, 1e-12);
  EXPECT_THROW(waypointPathPoses({{0, 0, 0}}, 0.0), InvalidInputError);
  EXPECT_THROW(waypointPathPoses({{0, 0, 0}, {std::nan(""), 0, 0}}), InvalidInputError);
}

TEST(CoverageEvaluator, RejectsInvalidInput) {
  const PolygonWithHoles free_area{rectangle(0, 0, 30, 30), {}};
  const PolygonWithHoles offset_area{rectangle(1, 1, 29, 29), {}};
  const FrustumSensor sensor(4.0, 1.6, 0.4);
  EXPECT_THROW(CoverageEvaluator(free_area, {offset_area}, FrustumSensor(0.0, 1.0, 0.0)),
               InvalidInputError);
  EXPECT_THROW(CoverageEvaluator(free_area, {offset_area}, FrustumSensor(1.0, -1.0, 0.0)),
               InvalidInputError);
  EXPECT_THROW(CoverageEvaluator(free_area, {{rectangle(5, 5, 5.001, 5.001), {}}}, sensor),
               InvalidInputError);
  EXPECT_THROW(CoverageEvaluator({rectangle(0, 0, 0, 30), {}}, {offset_area}, sensor),
               InvalidInputError);
  const CoverageEvaluator evaluator(free_area, {offset_area}, sensor);
  const CoverageEvaluator other(free_area, {offset_area}, sensor, {0.5, 1e-3, 4'000'000});
  EXPECT_THROW(evaluator.report(other.seeTrajectory({{5, 5, 0}})), InvalidInputError);
  EXPECT_THROW(evaluator.lostArea(other.seeTrajectory({{5, 5, 0}}), evaluator.seeTrajectory({})),
               InvalidInputError);
}

// What one path fails to see of what another sees: a lane along y = 2 of a 40 m x 10 m
// area, 4 m wide and 2 m long, against the same lane stopped at x = 20. The second misses
// x 21 to 40, y 0 to 4 (76 m^2, 19 % of the area); with the offset free area y >= 3 the
// reachable area is y >= 2, so 38 m^2 of it are reachable. Nothing is lost to itself or to a
// path that sees more.
TEST(CoverageEvaluator, MeasuresWhatOnePathLosesOfAnothersView) {
  const PolygonWithHoles area{rectangle(0, 0, 40, 10), {}};
  const PolygonWithHoles offset{rectangle(0, 3, 40, 10), {}};
  const FrustumSensor sensor(4.0, 2.0, 0.0);
  for (const double angle : {0.0, 0.2}) {
    SCOPED_TRACE("grid angle " + std::to_string(angle));
    const CoverageEvaluator evaluator(area, {offset}, sensor, {0.05}, angle);
    const SeenArea whole = evaluator.seeWaypointPath({{0, 2, 0}, {40, 2, 0}});
    const SeenArea half = evaluator.seeWaypointPath({{0, 2, 0}, {20, 2, 0}});
    const LostArea lost = evaluator.lostArea(whole, half);
    EXPECT_NEAR(lost.area_m2, 76.0, 1.0);
    EXPECT_NEAR(lost.reachable_area_m2, 38.0, 1.0);
    EXPECT_NEAR(lost.percent_of_free_area, 19.0, 0.25);
    for (const LostArea none :
         {evaluator.lostArea(whole, whole), evaluator.lostArea(half, whole)}) {
      EXPECT_EQ(none.area_m2, 0.0);
      EXPECT_EQ(none.reachable_area_m2, 0.0);
      EXPECT_EQ(none.percent_of_free_area, 0.0);
    }
  }
}

TEST(CoverageEvaluator, RandomMapsSweptOverTheirBoxAreFullyCovered) {
  // Maps like the planner's tests (hulls 50 to 200 m, up to 15 holes, footprints 2 to
  // 12.9 m): lanes over the whole bounding box see all of the reachable area.
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> size(50.0, 200.0);
  std::uniform_real_distribution<double> width(2.0, 12.9);
  double slowest_s = 0.0;
  double total_s = 0.0;
  int evaluated = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const PolygonWithHoles map = testing::randomMap(rng, size(rng), 15, 2.0);
    const FrustumSensor sensor(width(rng), 1.6, 0.4);
    OffsetFreeArea offset;
    try {
      offset = computeOffsetFreeArea(map, 1.0);
    } catch (const InvalidInputError&) {
      continue;
    }
    Point2 low = map.hull.front();
    Point2 high = map.hull.front();
    for (const Point2& p : map.hull) {
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
    std::vector<Pose2> waypoints =
        lawnmower(low.x(), high.x(), low.y(), high.y(), sensor.sweepDistance());
    // Duplicates and zero-length legs on the way.
    waypoints.insert(waypoints.begin() + 3, waypoints[2]);
    waypoints.push_back(waypoints.back());
    const auto start = std::chrono::steady_clock::now();
    const double coverage =
        waypointPathReachableCoveragePercent(map, offset.parts, sensor, waypoints);
    const double elapsed_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    slowest_s = std::max(slowest_s, elapsed_s);
    total_s += elapsed_s;
    EXPECT_GE(coverage, 99.99) << "trial " << trial;
    ++evaluated;
  }
  EXPECT_GE(evaluated, 15);
  std::printf("%d random maps: evaluation %.3f s on average, %.3f s at most\n", evaluated,
              total_s / evaluated, slowest_s);
}

TEST(CoverageEvaluator, LargeMapIsCovered) {
  // A 200 m x 200 m map with 16 square holes, footprint 2 m x 1.6 m, 40 % overlap:
  // 167 lanes. Prints the time to rasterize, sweep and count (speed is not asserted here).
  PolygonWithHoles free_area{rectangle(0, 0, 200, 200), {}};
  PolygonWithHoles offset_area{rectangle(1, 1, 199, 199), {}};
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      const double x = 30.0 + 45.0 * i;
      const double y = 30.0 + 45.0 * j;
      free_area.holes.push_back(rectangle(x, y, x + 10, y + 10, true));
      offset_area.holes.push_back(rectangle(x - 1, y - 1, x + 11, y + 11, true));
    }
  }
  const FrustumSensor sensor(2.0, 1.6, 0.4);
  const std::vector<Pose2> waypoints = lawnmower(1, 199, 1, 199, sensor.sweepDistance());
  for (const std::size_t max_cells : {std::size_t{4'000'000}, std::size_t{1'000'000}}) {
    const auto start = std::chrono::steady_clock::now();
    const CoverageEvaluator evaluator(free_area, {offset_area}, sensor, {0.0, 1e-3, max_cells});
    const auto prepared = std::chrono::steady_clock::now();
    const CoverageReport report = evaluator.report(evaluator.seeWaypointPath(waypoints));
    const auto end = std::chrono::steady_clock::now();
    const double prepare_s = std::chrono::duration<double>(prepared - start).count();
    const double sweep_s = std::chrono::duration<double>(end - prepared).count();
    std::printf("200 m map, %zu cells of %.3f m: masks %.3f s, sweep and count %.3f s\n",
                evaluator.raster().cellCount(), evaluator.raster().cellSize(), prepare_s, sweep_s);
    // The lanes pass over the holes too, so the whole reachable area is seen.
    EXPECT_GE(report.reachable_coverage_percent, 99.9);
    EXPECT_NEAR(evaluator.raster().area(evaluator.freeArea()), 40000.0 - 1600.0, 38.4);
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
