#include "trajectory_generation_tools/trajectory/continuous_curvature_turn.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// The arc of `radius` tangent to a leg heading `yaw` at `start`, turning by `turn`.
PathPrimitive arcFrom(const Point2& start, double yaw, double radius, double turn) {
  const double side = turn > 0.0 ? 1.0 : -1.0;
  const Point2 centre = start + side * radius * Point2(-std::sin(yaw), std::cos(yaw));
  const Point2 from_centre = start - centre;
  return PathPrimitive::arc(centre, radius, std::atan2(from_centre.y(), from_centre.x()), turn);
}

/// Checks the properties every continuous-curvature turn has, for `arc` and `rate`.
void expectContinuousTurn(const PathPrimitive& arc, double rate) {
  const std::optional<ContinuousCurvatureTurnShape> shape =
      ContinuousCurvatureTurn::replacing(arc, rate);
  ASSERT_TRUE(shape.has_value());
  const std::vector<PathPrimitive>& turn = shape->primitives;
  ASSERT_GE(turn.size(), 2u);
  EXPECT_GE(shape->extension, 0.0);
  // It starts on the incoming leg and ends on the outgoing one, `extension` beyond the
  // arc's ends, with the legs' headings.
  const Pose2 in = arc.startPose();
  const Pose2 out = arc.endPose();
  const Point2 start = arc.start() - shape->extension * Point2(std::cos(in.yaw), std::sin(in.yaw));
  const Point2 end = arc.end() + shape->extension * Point2(std::cos(out.yaw), std::sin(out.yaw));
  EXPECT_LT((turn.front().start() - start).norm(), 1e-9);
  EXPECT_LT((turn.back().end() - end).norm(), 1e-6);
  EXPECT_NEAR(wrapAngle(turn.front().startPose().yaw - in.yaw), 0.0, 1e-12);
  EXPECT_NEAR(wrapAngle(turn.back().endPose().yaw - out.yaw), 0.0, 1e-6);
  // Curvature: 0 at both ends, continuous at every join (G2), never above the arc's, and
  // changing by at most the rate per metre.
  EXPECT_EQ(turn.front().curvatureAt(0.0), 0.0);
  EXPECT_NEAR(turn.back().curvatureAt(1.0), 0.0, 1e-9);
  for (std::size_t i = 0; i < turn.size(); ++i) {
    EXPECT_LE(turn[i].curvature(), arc.curvature() + 1e-12) << i;
    if (turn[i].kind() == PrimitiveKind::kClothoid) {
      EXPECT_LE(std::abs(turn[i].curvatureRate()), rate + 1e-12) << i;
    }
    if (i > 0) {
      EXPECT_LT((turn[i].start() - turn[i - 1].end()).norm(), 1e-9) << i;
      EXPECT_NEAR(wrapAngle(turn[i].startPose().yaw - turn[i - 1].endPose().yaw), 0.0, 1e-9) << i;
      EXPECT_NEAR(turn[i].curvatureAt(0.0), turn[i - 1].curvatureAt(1.0), 1e-9) << i;
    }
  }
}

TEST(ContinuousCurvatureTurnTest, ReplacesArcsOfEveryTurnAndSide) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> yaw(-M_PI, M_PI);
  std::uniform_real_distribution<double> radius(0.2, 3.0);
  std::uniform_real_distribution<double> turn(0.01, M_PI - 0.01);
  std::uniform_real_distribution<double> rate(0.3, 8.0);
  for (int trial = 0; trial < 200; ++trial) {
    const double side = trial % 2 == 0 ? 1.0 : -1.0;
    const PathPrimitive arc =
        arcFrom({yaw(random), yaw(random)}, yaw(random), radius(random), side * turn(random));
    SCOPED_TRACE(trial);
    expectContinuousTurn(arc, rate(random));
  }
}

TEST(ContinuousCurvatureTurnTest, ReachesTheArcsCurvatureWhereTheTurnIsLargeEnough) {
  // A right angle of radius 1 at rate 2: the clothoids turn 0.25 rad each, 0.5 m long, and
  // the arc between them keeps curvature 1 over the remaining 1.07 rad.
  const PathPrimitive arc = arcFrom({0, 0}, 0.0, 1.0, M_PI / 2);
  const auto shape = ContinuousCurvatureTurn::replacing(arc, 2.0);
  ASSERT_TRUE(shape);
  ASSERT_EQ(shape->primitives.size(), 3u);
  EXPECT_NEAR(shape->primitives[0].length(), 0.5, 1e-15);
  EXPECT_NEAR(shape->primitives[0].turnAngle(), 0.25, 1e-15);
  EXPECT_EQ(shape->primitives[1].kind(), PrimitiveKind::kArc);
  EXPECT_NEAR(shape->primitives[1].turnAngle(), M_PI / 2 - 0.5, 1e-12);
  // The classic spiral shift: about half a clothoid's length (0.25 m) and a little more.
  EXPECT_GT(shape->extension, 0.25);
  EXPECT_LT(shape->extension, 0.27);
}

TEST(ContinuousCurvatureTurnTest, ASmallTurnIsTwoClothoidsBelowTheArcsCurvature) {
  const PathPrimitive arc = arcFrom({0, 0}, 0.0, 1.0, 0.2);
  const auto shape = ContinuousCurvatureTurn::replacing(arc, 2.0);
  ASSERT_TRUE(shape);
  ASSERT_EQ(shape->primitives.size(), 2u);
  EXPECT_NEAR(shape->primitives[0].curvature(), std::sqrt(0.2 * 2.0), 1e-12);
  expectContinuousTurn(arc, 2.0);
}

TEST(ContinuousCurvatureTurnTest, RefusesWhatItCannotReplace) {
  EXPECT_FALSE(ContinuousCurvatureTurn::replacing(PathPrimitive::segment({0, 0}, {1, 0}), 1.0));
  EXPECT_FALSE(ContinuousCurvatureTurn::replacing(arcFrom({0, 0}, 0.0, 1.0, M_PI), 1.0));
  EXPECT_FALSE(ContinuousCurvatureTurn::replacing(arcFrom({0, 0}, 0.0, 1.0, 1e-9), 1.0));
  EXPECT_FALSE(ContinuousCurvatureTurn::replacing(arcFrom({0, 0}, 0.0, 1.0, 1.0), 0.0));
}

}  // namespace
}  // namespace kinematic_coverage::core
