#include "trajectory_generation_tools/replanning/remaining_area.h"

#include <gtest/gtest.h>

#include <cmath>

#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"
#include "polygon_coverage_ros_bridge/validation/polygon_validator.h"

namespace kinematic_coverage::core {
namespace {

/// A line sensor 2 m wide: a straight pass sees a 2 m band.
PlannerParameters lineSensor() {
  PlannerParameters parameters;
  parameters.sensor_model = "line";
  parameters.lateral_footprint = 2.0;
  parameters.lateral_overlap = 0.0;
  return parameters;
}

PolygonWithHoles square(double size) { return {{{0, 0}, {size, 0}, {size, size}, {0, size}}, {}}; }

/// A straight pass along y = y0 from x = 0 to x = length.
std::vector<Pose2> pass(double y0, double length, double step = 0.5) {
  std::vector<Pose2> poses;
  for (double x = 0.0; x <= length + 1e-9; x += step) poses.push_back({x, y0, 0.0});
  return poses;
}

std::size_t vertexCount(const std::vector<PolygonWithHoles>& parts) {
  std::size_t count = 0;
  for (const PolygonWithHoles& part : parts) {
    count += part.hull.size();
    for (const Ring& hole : part.holes) count += hole.size();
  }
  return count;
}

TEST(RemainingArea, AStraightPassLeavesTheRestOfTheSquare) {
  PlannerParameters parameters = lineSensor();
  const RemainingArea remaining = RemainingAreaCalculator(remainingAreaOptionsOf(parameters))
                                      .compute(square(20), pass(1.0, 20.0));
  EXPECT_NEAR(remaining.free_area_m2, 400.0, 1.0);
  EXPECT_NEAR(remaining.seen_area_m2, 40.0, 1.0);
  EXPECT_NEAR(remaining.remaining_area_m2, 360.0, 1.0);
  ASSERT_EQ(remaining.parts.size(), 1u);
  // Simplification moves the boundary by at most its tolerance (the 0.4 m opening rounds
  // the corners, and chamfering them shifts the sides by up to 0.1 m).
  const double perimeter = 2.0 * (20.0 + 18.0);
  EXPECT_LE(area(remaining.parts[0]), 360.0 + 1e-6);
  EXPECT_GE(area(remaining.parts[0]), 360.0 - parameters.replanning_simplify_tolerance * perimeter);
  for (const Point2& p : remaining.parts[0].hull) EXPECT_GE(p.y(), 2.0 - 1e-9);
  EXPECT_NO_THROW(PolygonValidator().validate(remaining.parts[0]));
}

TEST(RemainingArea, PartsSmallerThanTheMinimumAreDroppedWithTheirAreaAndCentroid) {
  PlannerParameters parameters = lineSensor();
  parameters.replanning_min_area = 5.0;
  // Passes along y = 1 and y = 3 over x in [0, 3] of a 4 m square: a 1 m x 4 m strip at
  // x in [3, 4] stays unseen, smaller than 5 m^2.
  std::vector<Pose2> visited = pass(1.0, 3.0);
  const std::vector<Pose2> second = pass(3.0, 3.0);
  visited.insert(visited.end(), second.rbegin(), second.rend());
  const RemainingArea remaining =
      RemainingAreaCalculator(remainingAreaOptionsOf(parameters)).compute(square(4), visited);
  EXPECT_TRUE(remaining.parts.empty());
  ASSERT_EQ(remaining.dropped.size(), 1u);
  EXPECT_NEAR(remaining.dropped[0].area_m2, 4.0, 0.3);
  EXPECT_NEAR(remaining.dropped[0].centroid.x(), 3.5, 0.1);
  EXPECT_NEAR(remaining.dropped[0].centroid.y(), 2.0, 0.1);
  // At a smaller minimum it is kept.
  parameters.replanning_min_area = 1.0;
  const RemainingArea kept =
      RemainingAreaCalculator(remainingAreaOptionsOf(parameters)).compute(square(4), visited);
  EXPECT_EQ(kept.parts.size(), 1u);
  EXPECT_TRUE(kept.dropped.empty());
}

/// The thesis's slivers: passes that leave a strip narrower than the sliver width between
/// them; the strip is opened away, the wide part stays.
TEST(RemainingArea, SliversNarrowerThanTheFractionGo) {
  PlannerParameters parameters = lineSensor();
  parameters.replanning_sliver_fraction = 0.2;  // 0.4 m with a 2 m spacing
  // Out along y = 1 and back along y = 3.3: a 0.3 m strip at y in [2, 2.3] stays unseen.
  std::vector<Pose2> visited = pass(1.0, 20.0);
  const std::vector<Pose2> second = pass(3.3, 20.0);
  visited.insert(visited.end(), second.rbegin(), second.rend());
  const RemainingArea remaining =
      RemainingAreaCalculator(remainingAreaOptionsOf(parameters)).compute(square(20), visited);
  ASSERT_EQ(remaining.parts.size(), 1u);
  EXPECT_NEAR(area(remaining.parts[0]), 20.0 * (20.0 - 4.3), 0.1 * 2.0 * (20.0 + 15.7));
  for (const Point2& p : remaining.parts[0].hull) EXPECT_GT(p.y(), 4.0);
  // With no opening the strip stays as its own part.
  parameters.replanning_sliver_fraction = 0.0;
  EXPECT_EQ(RemainingAreaCalculator(remainingAreaOptionsOf(parameters))
                .compute(square(20), visited)
                .parts.size(),
            2u);
}

/// The thesis's many vertices: a wavy visited path leaves a boundary that, traced on the
/// raster, is a staircase of hundreds of cell corners; the parts keep a few dozen
/// vertices, stay valid and keep their area.
TEST(RemainingArea, WavyBoundariesAreSimplified) {
  PlannerParameters parameters = lineSensor();
  std::vector<Pose2> visited;
  for (int i = 0; i <= 200; ++i) {
    const double x = 0.1 * i;
    const double y = 6.0 + 1.5 * std::sin(0.9 * x);
    visited.push_back({x, y, std::atan(1.35 * std::cos(0.9 * x))});
  }
  const RemainingArea remaining =
      RemainingAreaCalculator(remainingAreaOptionsOf(parameters)).compute(square(20), visited);
  ASSERT_EQ(remaining.parts.size(), 2u);  // below and above the band
  EXPECT_LT(vertexCount(remaining.parts), 80u);
  for (const PolygonWithHoles& part : remaining.parts) {
    EXPECT_NO_THROW(PolygonValidator().validate(part));
  }
  const double perimeter = 4.0 * 20.0 + 2.0 * 25.0;
  EXPECT_NEAR(remaining.kept_area_m2, remaining.remaining_area_m2,
              parameters.replanning_simplify_tolerance * perimeter);
}

/// The thesis's non-simple concave hull (Fig. 3.12): a U-shaped visited path whose alpha
/// shape encloses an unvisited pocket. Its triangles are rasterized, so the remaining
/// parts are valid polygons whatever the shape.
TEST(RemainingArea, ConcaveHullOfAUTurnGivesValidParts) {
  PlannerParameters parameters = lineSensor();
  parameters.replanning_method = "concave_hull";
  parameters.alpha = 1.5;
  std::vector<Pose2> visited = pass(3.0, 16.0);
  for (double y = 3.0; y <= 15.0; y += 0.5) visited.push_back({16.0, y, M_PI / 2});
  for (double x = 16.0; x >= 0.0; x -= 0.5) visited.push_back({x, 15.0, M_PI});
  const RemainingArea remaining =
      RemainingAreaCalculator(remainingAreaOptionsOf(parameters)).compute(square(20), visited);
  EXPECT_FALSE(remaining.parts.empty());
  for (const PolygonWithHoles& part : remaining.parts) {
    EXPECT_NO_THROW(PolygonValidator().validate(part));
  }
  // The pocket between the arms stays to be covered with a small alpha.
  bool pocket = false;
  for (const PolygonWithHoles& part : remaining.parts) pocket = pocket || contains(part, {8, 9});
  EXPECT_TRUE(pocket);
  // The convex hull swallows the pocket.
  parameters.replanning_method = "convex_hull";
  const RemainingArea convex =
      RemainingAreaCalculator(remainingAreaOptionsOf(parameters)).compute(square(20), visited);
  for (const PolygonWithHoles& part : convex.parts) EXPECT_FALSE(contains(part, {8, 9}));
  EXPECT_LT(convex.kept_area_m2, remaining.kept_area_m2);
}

TEST(RemainingArea, NonFinitePoseIsInvalid) {
  EXPECT_THROW(RemainingAreaCalculator(remainingAreaOptionsOf(lineSensor()))
                   .compute(square(10), std::vector<Pose2>{{0, std::nan(""), 0}}),
               InvalidInputError);
}

}  // namespace
}  // namespace kinematic_coverage::core
