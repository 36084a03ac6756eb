#include "polygon_coverage_ros_bridge/decomposition/sweep_direction.h"

#include <gtest/gtest.h>

#include <cmath>

namespace kinematic_coverage::core {
namespace {

TEST(SweepDirection, FrameRoundTripAndDirectionMapsToY) {
  for (double direction : {0.0, 0.3, M_PI / 2, 2.5}) {
    const Point2 p(3.0, -2.0);
    EXPECT_TRUE(fromSweepFrame(toSweepFrame(p, direction), direction).isApprox(p));
    const Point2 d = toSweepFrame(directionVector(direction), direction);
    EXPECT_NEAR(d.x(), 0.0, 1e-12);
    EXPECT_NEAR(d.y(), 1.0, 1e-12);
  }
}

TEST(SweepDirection, AltitudeOfRectangle) {
  const Ring rectangle = {{0, 0}, {10, 0}, {10, 2}, {0, 2}};
  EXPECT_NEAR(altitude(rectangle, 0.0), 2.0, 1e-12);
  EXPECT_NEAR(altitude(rectangle, M_PI / 2), 10.0, 1e-12);
}

TEST(SweepDirection, MonotoneDetectsUShape) {
  const Ring u = {{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
  EXPECT_FALSE(isMonotone(u, 0.0));      // horizontal lanes would leave it
  EXPECT_TRUE(isMonotone(u, M_PI / 2));  // vertical lines meet it once
  const Ring triangle = {{0, 0}, {4, 0}, {1, 3}};
  for (double direction = 0.0; direction < M_PI; direction += 0.1) {
    EXPECT_TRUE(isMonotone(triangle, direction)) << direction;
  }
}

TEST(SweepDirection, CandidatesDeduplicatedAndBounded) {
  const Ring square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const auto directions = candidateDirections({square}, 10);
  EXPECT_EQ(directions.size(), 2u);
  Ring many;
  for (int i = 0; i < 2000; ++i) {
    const double a = 2.0 * M_PI * i / 2000;
    many.emplace_back(std::cos(a), std::sin(a));
  }
  EXPECT_EQ(candidateDirections({many}, 16).size(), 16u);
  // Nearly parallel edges (and edges near 0 and pi) merge.
  const Ring sliver = {{0, 0}, {10, 1e-5}, {10, 1}, {0, 1 - 1e-5}};
  EXPECT_EQ(candidateDirections({sliver}, 10).size(), 2u);
}

}  // namespace
}  // namespace kinematic_coverage::core
