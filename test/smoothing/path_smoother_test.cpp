#include "trajectory_generation_tools/smoothing/path_smoother.h"

#include <gtest/gtest.h>

#include <cmath>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "test/smoothing/smoothing_oracle.h"
#include "trajectory_generation_tools/smoothing/corner_geometry.h"

namespace kinematic_coverage::core {
namespace {

TEST(PathSmoother, RejectsInvalidInput) {
  EXPECT_THROW(PathSmoother({}, 0.0), InvalidInputError);
  EXPECT_THROW(PathSmoother({}, -1.0), InvalidInputError);
  EXPECT_THROW(PathSmoother({}, std::nan("")), InvalidInputError);
  PolygonWithHoles bad;
  bad.hull = {{0, 0}, {1, 0}, {std::nan(""), 1}};
  EXPECT_THROW(PathSmoother(bad, 1.0), InvalidInputError);
  const PathSmoother smoother({}, 1.0);
  EXPECT_THROW(smoother.smooth(std::vector<Point2>{{0, 0}, {std::nan(""), 1}}), InvalidInputError);
}

TEST(PathSmoother, FewerThanTwoDistinctWaypointsGiveNoPath) {
  const PathSmoother smoother({}, 1.0);
  EXPECT_TRUE(smoother.smooth(std::vector<Point2>{}).primitives.empty());
  EXPECT_TRUE(smoother.smooth(std::vector<Point2>{{1, 1}, {1, 1}}).primitives.empty());
  const SmoothedPath one_leg = smoother.smooth(std::vector<Point2>{{0, 0}, {3, 4}});
  ASSERT_EQ(one_leg.primitives.size(), 1u);
  EXPECT_DOUBLE_EQ(one_leg.primitives[0].length(), 5.0);
}

TEST(PathSmoother, DuplicateAndCollinearWaypointsAreDropped) {
  const PathSmoother smoother({}, 1.0);
  const SmoothedPath plain = smoother.smooth(std::vector<Point2>{{0, 0}, {10, 0}, {10, 10}});
  const SmoothedPath noisy = smoother.smooth(std::vector<Point2>{
      {0, 0}, {0, 0}, {4, 0}, {7, 0}, {10, 0}, {10, 0}, {10, 5}, {10, 10}, {10, 10}});
  ASSERT_EQ(plain.primitives.size(), noisy.primitives.size());
  for (std::size_t i = 0; i < plain.primitives.size(); ++i) {
    EXPECT_TRUE(plain.primitives[i].start().isApprox(noisy.primitives[i].start(), 1e-12));
    EXPECT_TRUE(plain.primitives[i].end().isApprox(noisy.primitives[i].end(), 1e-12));
  }
  EXPECT_EQ(noisy.statistics.turns_total, 1);
  EXPECT_EQ(noisy.statistics.inner, 1);
  const SmoothedPath straight =
      smoother.smooth(std::vector<Point2>{{0, 0}, {1, 1}, {2, 2}, {2, 2}, {5, 5}});
  ASSERT_EQ(straight.primitives.size(), 1u);
  EXPECT_EQ(straight.statistics.turns_total, 0);
}

TEST(PathSmoother, ReversalsShortLegsAndPosesGiveAContinuousPath) {
  const PathSmoother smoother({}, 1.0);
  // A reversal, legs between r and 2r, a leg shorter than r / tan(ABC / 2).
  const std::vector<Point2> points{{0, 0},     {10, 0},    {0, 0},    {0, 1.5},
                                   {1.5, 1.5}, {1.5, 1.8}, {-5, 1.9}, {-5, 8}};
  const SmoothedPath path = smoother.smooth(points);
  testing::expectContinuousPath(path, 10.0);
  EXPECT_EQ(path.statistics.turns_total, 6);
  EXPECT_GE(path.statistics.turns_smoothed, 3);
  std::vector<Pose2> poses;
  for (const Point2& p : points) poses.push_back({p.x(), p.y(), 0.3});
  const SmoothedPath from_poses = smoother.smooth(poses);
  ASSERT_EQ(from_poses.primitives.size(), path.primitives.size());
  EXPECT_EQ(from_poses.statistics.turns_smoothed, path.statistics.turns_smoothed);
}

TEST(PathSmoother, ExampleUsesEveryVariant) {
  // Open right angles at (10, 0) and (10, 10) (inner); an obstacle on the inner side of
  // (20, 10) (outer, bisector boundary); at (20, 20) an obstacle on the inner side and a
  // 1.5 r leg after it (outer, tangent intersection boundary, ending exactly at (21.5, 20),
  // which then has no leg left to smooth and stays sharp).
  PolygonWithHoles area;
  area.hull = testing::squareHull({20, 20}, 40);
  area.holes.push_back(testing::rectangleHole({19.35, 10.25}, {19.75, 10.65}));  // inside (20, 10)
  area.holes.push_back(testing::rectangleHole({20.25, 19.35}, {20.65, 19.75}));  // inside (20, 20)
  const std::vector<Point2> points{{0, 0},   {10, 0},    {10, 10},  {20, 10},
                                   {20, 20}, {21.5, 20}, {21.5, 30}};
  const PathSmoother smoother(area, 1.0);
  const SmoothedPath path = smoother.smooth(points);
  testing::expectContinuousPath(path, 40.0);
  EXPECT_EQ(path.statistics.turns_total, 5);
  EXPECT_EQ(path.statistics.inner, 2);
  EXPECT_EQ(path.statistics.outer_bisector, 1);
  EXPECT_EQ(path.statistics.outer_tangent, 1);
  EXPECT_EQ(path.statistics.turns_smoothed, 4);
  for (const PathPrimitive& p : path.primitives) {
    if (p.kind() == PrimitiveKind::kArc) {
      EXPECT_GT(testing::sampledArcClearance(area, p, 0.01), 1e-9);
    } else {
      EXPECT_GT(testing::segmentClearance(area, p.start(), p.end()), 1e-9);
    }
  }
}

TEST(PathSmoother, BoustrophedonIsFullySmoothed) {
  std::vector<Point2> lanes;
  for (int i = 0; i < 20; ++i) {
    lanes.push_back({2.0 * i, i % 2 == 0 ? 0.0 : 100.0});
    lanes.push_back({2.0 * i, i % 2 == 0 ? 100.0 : 0.0});
  }
  PolygonWithHoles area;
  area.hull = {{-5, -5}, {45, -5}, {45, 105}, {-5, 105}};
  const SmoothedPath path = PathSmoother(area, 1.0).smooth(lanes);
  testing::expectContinuousPath(path, 100.0);
  EXPECT_EQ(path.statistics.turns_total, 38);
  EXPECT_EQ(path.statistics.turns_smoothed, 38);
  EXPECT_EQ(path.statistics.inner, 38);
}

}  // namespace
}  // namespace kinematic_coverage::core
