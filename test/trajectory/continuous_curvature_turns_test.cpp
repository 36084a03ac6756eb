#include "trajectory_generation_tools/trajectory/continuous_curvature_turns.h"

#include <gtest/gtest.h>

#include <cmath>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "trajectory_generation_tools/trajectory/primitive_path_metrics.h"
#include "trajectory_generation_tools/trajectory/primitive_path_validation.h"

namespace kinematic_coverage::core {
namespace {

/// A 20 m square.
PolygonWithHoles square() {
  PolygonWithHoles area;
  area.hull = {{0, 0}, {20, 0}, {20, 20}, {0, 20}};
  return area;
}

/// From (x_start, 2) east to the corner (10, 2), a left arc of radius 1 inscribed in it,
/// and north to (10, y_end).
std::vector<PathPrimitive> rightAngle(double x_start, double y_end) {
  return {
      PathPrimitive::segment({x_start, 2}, {9, 2}),
      PathPrimitive::arc({9, 3}, 1.0, -M_PI / 2, M_PI / 2).withVariant(SmoothingVariant::kInner),
      PathPrimitive::segment({10, 3}, {10, y_end})};
}

TEST(ContinuousCurvatureTurnsTest, ReplacesAnArcBetweenLegsAndKeepsTheEnds) {
  const std::vector<PathPrimitive> path = rightAngle(2.0, 10.0);
  const ContinuousCurvaturePath result =
      ContinuousCurvatureTurns(square(), 2.0).apply(path, nullptr);
  EXPECT_EQ(result.turns_clothoid, 1);
  ASSERT_EQ(result.primitives.size(), 5u);  // leg, clothoid, arc, clothoid, leg
  EXPECT_EQ(result.primitives[1].kind(), PrimitiveKind::kClothoid);
  EXPECT_EQ(result.primitives[1].variant(), SmoothingVariant::kInner);
  EXPECT_NO_THROW(validatePrimitivePath(result.primitives));
  EXPECT_EQ(result.primitives.front().start(), path.front().start());
  EXPECT_LT((result.primitives.back().end() - path.back().end()).norm(), 1e-6);
  EXPECT_LE(primitivePathMaxCurvature(result.primitives), 1.0 + 1e-12);
  // The legs gave up the extension, about a quarter metre each.
  EXPECT_LT(result.primitives.front().length(), path.front().length() - 0.25);
  EXPECT_LT(result.primitives.back().length(), path.back().length() - 0.25);
}

TEST(ContinuousCurvatureTurnsTest, KeepsTheArcWhereALegIsTooShort) {
  const std::vector<PathPrimitive> path = rightAngle(8.9, 10.0);  // a 0.1 m leg
  const ContinuousCurvaturePath result =
      ContinuousCurvatureTurns(square(), 2.0).apply(path, nullptr);
  EXPECT_EQ(result.turns_clothoid, 0);
  EXPECT_EQ(result.kept_for_room, 1);
  ASSERT_EQ(result.primitives.size(), path.size());
  EXPECT_EQ(result.primitives[1].kind(), PrimitiveKind::kArc);
}

TEST(ContinuousCurvatureTurnsTest, KeepsTheArcWhereTheTurnWouldComeNearerAnObstacle) {
  // The turn bends deeper into the corner than the arc: a small obstacle just inside the
  // arc's apex, 12 mm from it, is nearer the turn.
  PolygonWithHoles area = square();
  const Point2 centre(9, 3);
  const Point2 apex = centre + Point2(std::cos(-M_PI / 4), std::sin(-M_PI / 4));
  const Point2 inward = (centre - apex).normalized();
  const Point2 across(-inward.y(), inward.x());
  const Point2 tip = apex + 0.012 * inward;
  area.holes = {{tip, tip + 0.1 * inward + 0.05 * across, tip + 0.2 * inward,
                 tip + 0.1 * inward - 0.05 * across}};
  const ContinuousCurvaturePath result =
      ContinuousCurvatureTurns(area, 2.0).apply(rightAngle(2.0, 10.0), nullptr);
  EXPECT_EQ(result.turns_clothoid, 0);
  EXPECT_EQ(result.kept_for_clearance, 1);
  // Without it the same turn is taken.
  EXPECT_EQ(
      ContinuousCurvatureTurns(square(), 2.0).apply(rightAngle(2.0, 10.0), nullptr).turns_clothoid,
      1);
}

TEST(ContinuousCurvatureTurnsTest, TwoTurnsShareALegWhereItIsLongEnough) {
  // A U-turn: east, north 3 m between two left arcs, west. With a higher rate the
  // clothoids are short and both turns fit on the 1 m middle leg; with a low one neither
  // second turn does.
  const std::vector<PathPrimitive> u_turn{
      PathPrimitive::segment({2, 2}, {9, 2}), PathPrimitive::arc({9, 3}, 1.0, -M_PI / 2, M_PI / 2),
      PathPrimitive::segment({10, 3}, {10, 4}), PathPrimitive::arc({9, 4}, 1.0, 0.0, M_PI / 2),
      PathPrimitive::segment({9, 5}, {2, 5})};
  const ContinuousCurvaturePath short_spirals =
      ContinuousCurvatureTurns(square(), 8.0).apply(u_turn, nullptr);
  EXPECT_EQ(short_spirals.turns_clothoid, 2);
  EXPECT_NO_THROW(validatePrimitivePath(short_spirals.primitives));
  const ContinuousCurvaturePath long_spirals =
      ContinuousCurvatureTurns(square(), 0.5).apply(u_turn, nullptr);
  EXPECT_EQ(long_spirals.turns_clothoid, 0);
  EXPECT_EQ(long_spirals.kept_for_room, 2);
  EXPECT_NO_THROW(validatePrimitivePath(long_spirals.primitives));
}

TEST(ContinuousCurvatureTurnsTest, LeavesArcsInChainsAndRejectsABadRate) {
  // Two arcs in a row (an S): neither sits between two legs.
  const std::vector<PathPrimitive> s_curve{
      PathPrimitive::segment({2, 2}, {9, 2}), PathPrimitive::arc({9, 3}, 1.0, -M_PI / 2, M_PI / 4),
      PathPrimitive::arc({9 + 2 * std::cos(-M_PI / 4), 3 + 2 * std::sin(-M_PI / 4)}, 1.0,
                         3 * M_PI / 4, -M_PI / 4),
      PathPrimitive::segment({9 + 2 * std::cos(-M_PI / 4) - std::cos(3 * M_PI / 4 - M_PI / 4),
                              3 + 2 * std::sin(-M_PI / 4) + std::sin(3 * M_PI / 4 - M_PI / 4)},
                             {15, 4})};
  const ContinuousCurvaturePath result =
      ContinuousCurvatureTurns(square(), 2.0).apply(s_curve, nullptr);
  EXPECT_EQ(result.turns_clothoid, 0);
  EXPECT_EQ(result.primitives.size(), s_curve.size());
  EXPECT_THROW(ContinuousCurvatureTurns(square(), 0.0), InvalidInputError);
  EXPECT_THROW(ContinuousCurvatureTurns(square(), std::nan("")), InvalidInputError);
}

}  // namespace
}  // namespace kinematic_coverage::core
