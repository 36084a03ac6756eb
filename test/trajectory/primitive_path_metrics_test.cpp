#include "trajectory_generation_tools/trajectory/primitive_path_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "trajectory_generation_tools/trajectory/primitive_distance.h"

namespace kinematic_coverage::core {
namespace {

/// The distance from many points of the arc to [a, b]: an upper bound of the exact one,
/// within r * step of it.
double sampledArcDistance(const PathPrimitive& arc, const Point2& a, const Point2& b, int steps) {
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= steps; ++k) {
    best = std::min(best, distanceToSegment(arc.poseAt(double(k) / steps).position(), a, b));
  }
  return best;
}

TEST(PrimitiveDistance, ArcNearAWall) {
  // Quarter arc of radius 1 about the origin facing +x; wall x = 1.5.
  const PathPrimitive arc = PathPrimitive::arc({0, 0}, 1.0, -M_PI_4, M_PI_2);
  EXPECT_NEAR(distancePrimitiveToSegment(arc, {1.5, -5}, {1.5, 5}), 0.5, 1e-15);
  // The wall only above the arc's reach: nearest to the arc's end (cos 45, sin 45).
  const Point2 top(std::sqrt(0.5), std::sqrt(0.5));
  EXPECT_NEAR(distancePrimitiveToSegment(arc, {1.5, 2}, {1.5, 5}), (Point2(1.5, 2) - top).norm(),
              1e-15);
  // Behind the centre: from the arc's ends.
  EXPECT_NEAR(distancePrimitiveToSegment(arc, {-2, -5}, {-2, 5}), 2 + std::sqrt(0.5), 1e-15);
  // Crossing the arc, and a chord inside the circle.
  EXPECT_EQ(distancePrimitiveToSegment(arc, {0.5, 0}, {3, 0}), 0.0);
  EXPECT_NEAR(distancePrimitiveToSegment(arc, {0.2, -0.1}, {0.2, 0.1}), 1 - std::sqrt(0.05), 1e-15);
  // Its ends beyond the arc's angles: the arc's ends are nearest.
  EXPECT_NEAR(distancePrimitiveToSegment(arc, {0.2, -0.3}, {0.2, 0.3}),
              (Point2(0.2, 0.3) - top).norm(), 1e-15);
  // Clockwise arc, same points.
  const PathPrimitive clockwise = PathPrimitive::arc({0, 0}, 1.0, M_PI_4, -M_PI_2);
  EXPECT_NEAR(distancePrimitiveToSegment(clockwise, {1.5, -5}, {1.5, 5}), 0.5, 1e-15);
  // A point segment at the centre is r away.
  EXPECT_NEAR(distancePrimitiveToSegment(arc, {0, 0}, {0, 0}), 1.0, 1e-15);
}

TEST(PrimitiveDistance, SegmentsAndRotations) {
  const PathPrimitive segment = PathPrimitive::segment({0, 0}, {4, 0});
  EXPECT_EQ(distancePrimitiveToSegment(segment, {2, -1}, {2, 1}), 0.0);
  EXPECT_NEAR(distancePrimitiveToSegment(segment, {5, 1}, {6, 3}), std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(distancePrimitiveToSegment(segment, {1, 2}, {3, 0.5}), 0.5, 1e-15);
  EXPECT_NEAR(distancePrimitiveToSegment(PathPrimitive::rotation({1, 1}, 0, 1), {3, 0}, {3, 5}),
              2.0, 1e-15);
}

TEST(PrimitiveDistance, ArcToSegmentMatchesDenseSampling) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> coordinate(-3.0, 3.0);
  std::uniform_real_distribution<double> radius(0.1, 2.5);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  std::uniform_real_distribution<double> sweep(-2 * M_PI, 2 * M_PI);
  constexpr int kSteps = 2000;
  for (int trial = 0; trial < 3000; ++trial) {
    const double r = radius(rng);
    const double s = sweep(rng);
    const PathPrimitive arc =
        PathPrimitive::arc({coordinate(rng), coordinate(rng)}, r, angle(rng), s);
    const Point2 a(coordinate(rng), coordinate(rng));
    const Point2 b(coordinate(rng), coordinate(rng));
    const double exact = distancePrimitiveToSegment(arc, a, b);
    const double sampled = sampledArcDistance(arc, a, b, kSteps);
    ASSERT_TRUE(std::isfinite(exact));
    EXPECT_GE(exact, 0.0);
    EXPECT_LE(exact, sampled + 1e-12) << trial;
    // Between samples the arc strays at most r * (1 - cos(step / 2)) from its chord, and
    // a sample is at most half a step of arc from the nearest point.
    EXPECT_GE(exact, sampled - r * std::abs(s) / kSteps) << trial;
  }
}

TEST(PrimitivePathMetrics, LengthCurvatureAndClearance) {
  const PolygonWithHoles square{{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                                {{{6, 6}, {6, 8}, {8, 8}, {8, 6}}}};
  // Up x = 2, a clockwise U-turn of radius 1.5 whose top is at y = 9.5, down x = 5.
  const std::vector<PathPrimitive> path = {
      PathPrimitive::segment({2, 1}, {2, 8}), PathPrimitive::arc({3.5, 8}, 1.5, M_PI, -M_PI),
      PathPrimitive::segment({5, 8}, {5, 1}), PathPrimitive::rotation({5, 1}, -M_PI_2, M_PI)};
  EXPECT_NEAR(primitivePathLength(path), 7 + 1.5 * M_PI + 7, 1e-12);
  EXPECT_NEAR(primitivePathMaxCurvature(path), 1 / 1.5, 1e-15);
  // Nearest to the boundary: the arc's top at (3.5, 9.5), 0.5 from y = 10; the hole is 1
  // from x = 5, the start 1 from y = 0.
  EXPECT_NEAR(primitivePathClearance(path, square), 0.5, 1e-12);
  // Crossing a hole edge: clearance 0.
  EXPECT_EQ(primitivePathClearance({PathPrimitive::segment({5, 7}, {7, 7})}, square), 0.0);
  EXPECT_TRUE(std::isinf(primitivePathClearance({}, square)));
  EXPECT_EQ(primitivePathMaxCurvature({PathPrimitive::rotation({1, 1}, 0, 1)}), 0.0);
}

TEST(PrimitivePathMetrics, ClearanceEqualsTheSmallestPrimitiveDistance) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> coordinate(1.0, 19.0);
  const PolygonWithHoles area{{{0, 0}, {20, 0}, {20, 20}, {0, 20}},
                              {{{9, 9}, {9, 11}, {11, 11}, {11, 9}}}};
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<PathPrimitive> path;
    for (int i = 0; i < 5; ++i) {
      const Point2 a(coordinate(rng), coordinate(rng));
      path.push_back(i % 2 ? PathPrimitive::segment(a, {coordinate(rng), coordinate(rng)})
                           : PathPrimitive::arc(a, 0.5, coordinate(rng), 1.0));
    }
    double expected = std::numeric_limits<double>::infinity();
    for (const PathPrimitive& primitive : path) {
      for (const Ring* ring : {&area.hull, &area.holes[0]}) {
        for (std::size_t e = 0; e < ring->size(); ++e) {
          expected = std::min(
              expected,
              distancePrimitiveToSegment(primitive, (*ring)[e], (*ring)[(e + 1) % ring->size()]));
        }
      }
    }
    EXPECT_EQ(primitivePathClearance(path, area), expected);
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
