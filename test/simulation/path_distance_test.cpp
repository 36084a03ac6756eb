#include "trajectory_generation_tools/simulation/path_distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// The distance to the polyline by looking at every segment.
double bruteForceDistance(const std::vector<Point2>& points, const Point2& query) {
  if (points.size() == 1) return (query - points.front()).norm();
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < points.size(); ++i) {
    best = std::min(best, distanceToSegment(query, points[i - 1], points[i]));
  }
  return best;
}

TEST(PathDistanceTest, MatchesBruteForceNearAndFarFromRandomPaths) {
  std::mt19937 random(20240917);
  for (int trial = 0; trial < 30; ++trial) {
    // A random walk with steps from 1 mm to 5 m, some repeated points (rotations) and a
    // few long legs, so that the grid holds segments much longer than its cells.
    std::uniform_real_distribution<double> step(0.001, trial % 3 == 0 ? 40.0 : 5.0);
    std::uniform_real_distribution<double> angle(-M_PI, M_PI);
    std::vector<Point2> points{Point2(0, 0)};
    const int count = 2 + trial * 20;
    for (int i = 1; i < count; ++i) {
      if (i % 7 == 0) {
        points.push_back(points.back());
        continue;
      }
      const double a = angle(random);
      points.push_back(points.back() + step(random) * Point2(std::cos(a), std::sin(a)));
    }
    const PathDistance distance(points);
    std::uniform_real_distribution<double> offset(-200.0, 200.0);
    for (int q = 0; q < 200; ++q) {
      const Point2 near = points[q % points.size()] + 0.01 * Point2(offset(random), offset(random));
      const Point2 far = Point2(offset(random), offset(random)) * (q % 2 == 0 ? 1.0 : 50.0);
      for (const Point2& query : {near, far}) {
        EXPECT_NEAR(distance.distance(query), bruteForceDistance(points, query), 1e-9)
            << "trial " << trial << " query (" << query.x() << ", " << query.y() << ")";
      }
    }
  }
}

TEST(PathDistanceTest, PointsOnThePathAreAtZeroDistance) {
  const std::vector<Point2> points{{0, 0}, {10, 0}, {10, 0}, {10, 5}};
  const PathDistance distance(points);
  EXPECT_EQ(distance.distance(Point2(3.25, 0.0)), 0.0);
  EXPECT_EQ(distance.distance(Point2(10.0, 2.5)), 0.0);
  EXPECT_DOUBLE_EQ(distance.distance(Point2(5.0, 3.0)), 3.0);
  EXPECT_DOUBLE_EQ(distance.distance(Point2(13.0, 9.0)), 5.0);
}

TEST(PathDistanceTest, ASinglePointIsAPath) {
  const PathDistance distance({Point2(2, 3), Point2(2, 3)});
  EXPECT_DOUBLE_EQ(distance.distance(Point2(5, 7)), 5.0);
  EXPECT_EQ(distance.distance(Point2(2, 3)), 0.0);
}

TEST(PathDistanceTest, RejectsNoPointsAndNonFinitePoints) {
  EXPECT_THROW(PathDistance(std::vector<Point2>{}), InvalidInputError);
  EXPECT_THROW(PathDistance({Point2(0, 0), Point2(std::nan(""), 1)}), InvalidInputError);
}

}  // namespace
}  // namespace kinematic_coverage::core
