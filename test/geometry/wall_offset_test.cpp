#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// A counter-clockwise ring of n vertices around the origin, radius 150 m, every other vertex
/// pulled 5 cm inward (reflex) when `zigzag`.
Ring circle(int n, bool zigzag) {
  Ring ring;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * M_PI * i / n;
    const double r = 150.0 - (zigzag && i % 2 == 1 ? 0.05 : 0.0);
    ring.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return ring;
}

TEST(WallOffset, ShrinksASquareByTheWallDistance) {
  const PolygonWithHoles square = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {}};
  const OffsetFreeArea offset = computeOffsetFreeArea(square, 1.0);
  ASSERT_EQ(offset.parts.size(), 1u);
  EXPECT_NEAR(area(offset.parts.front()), 64.0, 1e-9);
}

TEST(WallOffset, RingsWhoseSkeletonWouldNotFitAreRefusedBeforeItIsBuilt) {
  // 6 000 vertices, 3 000 reflex: 18e6 vertex pairs, over 2 times the limit (the skeleton
  // would take about 900 MB); refused in milliseconds.
  const PolygonWithHoles noisy = {circle(6000, true), {}};
  try {
    computeOffsetFreeArea(noisy, 1.0);
    ADD_FAILURE() << "accepted";
  } catch (const InvalidInputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("the hull has 6000 vertices, 3000 of them reflex"), std::string::npos)
        << message;
    EXPECT_NE(message.find("18000000 pairs, 2.25 times the limit of 8000000"), std::string::npos)
        << message;
    EXPECT_NE(message.find("simplify the hull to fewer vertices"), std::string::npos) << message;
  }
  // The same ring as a hole is named by its index.
  PolygonWithHoles with_hole = {{{-500, -500}, {500, -500}, {500, 500}, {-500, 500}}, {}};
  with_hole.holes.push_back(circle(6000, true));
  std::reverse(with_hole.holes.back().begin(), with_hole.holes.back().end());
  EXPECT_THROW(
      {
        try {
          computeOffsetFreeArea(with_hole, 1.0);
        } catch (const InvalidInputError& error) {
          EXPECT_NE(std::string(error.what()).find("hole 0 has 6000 vertices"), std::string::npos)
              << error.what();
          throw;
        }
      },
      InvalidInputError);
  // Without a wall offset no skeleton is built, and nothing is refused.
  EXPECT_NO_THROW(computeOffsetFreeArea(noisy, 0.0));
}

TEST(WallOffset, ManyConvexVerticesAreNotLimited) {
  // 6 000 vertices, none reflex: the skeleton stays small, the offset is computed.
  const PolygonWithHoles round = {circle(6000, false), {}};
  const OffsetFreeArea offset = computeOffsetFreeArea(round, 1.0);
  EXPECT_NEAR(area(offset.parts), area(round) * std::pow(149.0 / 150.0, 2), 1.0);
}

}  // namespace
}  // namespace kinematic_coverage::core
