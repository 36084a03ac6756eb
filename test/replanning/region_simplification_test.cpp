#include "trajectory_generation_tools/replanning/region_simplification.h"

#include <gtest/gtest.h>

#include <cmath>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/validation/polygon_validator.h"

namespace kinematic_coverage::core {
namespace {

/// A square whose bottom side is a staircase of `steps` steps of `step` metres, with a
/// square hole close to the staircase.
PolygonWithHoles staircaseSquare(int steps, double step) {
  PolygonWithHoles polygon;
  for (int i = 0; i < steps; ++i) {
    polygon.hull.emplace_back(i * step, (i % 2) * step);
    polygon.hull.emplace_back((i + 1) * step, (i % 2) * step);
  }
  const double size = steps * step;
  polygon.hull.emplace_back(size, size);
  polygon.hull.emplace_back(0.0, size);
  polygon.holes.push_back({{1.0, 0.3}, {1.0, 1.0}, {2.0, 1.0}, {2.0, 0.3}});
  return polygon;
}

TEST(RegionSimplification, StaircasesGoHolesStayAndNothingCrosses) {
  const PolygonWithHoles input = staircaseSquare(200, 0.05);
  ASSERT_NO_THROW(PolygonValidator().validate(input));
  const PolygonWithHoles simplified = simplifyPolygon(input, 0.1);
  EXPECT_LT(simplified.hull.size(), 20u);
  ASSERT_EQ(simplified.holes.size(), 1u);
  EXPECT_NO_THROW(PolygonValidator().validate(simplified));
  EXPECT_GT(signedArea(simplified.hull), 0.0);
  EXPECT_LT(signedArea(simplified.holes[0]), 0.0);
  EXPECT_NEAR(area(simplified), area(input), 0.1 * 4 * 10.0);
  // Every kept vertex is a vertex of the input.
  for (const Point2& p : simplified.hull) {
    EXPECT_LT(distanceToRing(p, input.hull), 1e-12);
  }
}

TEST(RegionSimplification, ZeroToleranceKeepsThePolygonAndBadToleranceThrows) {
  const PolygonWithHoles input = staircaseSquare(10, 0.5);
  EXPECT_EQ(simplifyPolygon(input, 0.0).hull.size(), input.hull.size());
  EXPECT_THROW(simplifyPolygon(input, -1.0), InvalidInputError);
  EXPECT_THROW(simplifyPolygon(input, std::nan("")), InvalidInputError);
}

}  // namespace
}  // namespace kinematic_coverage::core
