#include "trajectory_generation_tools/smoothing/bulb_turn_smoothing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "test/smoothing/smoothing_oracle.h"

namespace kinematic_coverage::core {
namespace {

/// Expects the turn to leave [a, b1] with its heading, join [b2, c] with its heading, run
/// as consecutive tangent pieces (arcs of `radius`, at most one straight run) turning as
/// much as the two corners do, report where it touches the legs, and stay on the near side
/// of the line through b1 and b2 (the boundary the lanes end at), touching it.
void expectBulbTurn(const Point2& a, const Point2& b1, const Point2& b2, const Point2& c,
                    double radius, const CornerSmoothing& turn) {
  const double gap = testing::kRelativeGap *
                     std::max({(a - b1).norm(), (c - b2).norm(), radius, b1.norm(), b2.norm()});
  ASSERT_GE(turn.arcs.size(), 2u);
  ASSERT_LE(turn.arcs.size(), 5u);
  EXPECT_EQ(turn.corners, 2);
  EXPECT_EQ(turn.variant, SmoothingVariant::kBulb);
  const PathPrimitive& first = turn.arcs.front();
  const PathPrimitive& last = turn.arcs.back();
  EXPECT_LE(distanceToSegment(first.start(), a, b1), gap);
  EXPECT_LE(testing::headingGap(first.startPose().yaw, headingOf(a, b1)), testing::kHeadingGap);
  EXPECT_LE(distanceToSegment(last.end(), b2, c), gap);
  EXPECT_LE(testing::headingGap(last.endPose().yaw, headingOf(b2, c)), testing::kHeadingGap);
  EXPECT_NEAR((first.start() - b1).norm(), turn.entry_distance, gap);
  EXPECT_NEAR((last.end() - b2).norm(), turn.exit_distance, gap);

  const Point2 d1 = (b1 - a).normalized();
  const Point2 d2 = (b2 - b1).normalized();
  const Point2 d3 = (c - b2).normalized();
  const double corners_turn = std::atan2(d1.x() * d2.y() - d1.y() * d2.x(), d1.dot(d2)) +
                              std::atan2(d2.x() * d3.y() - d2.y() * d3.x(), d2.dot(d3));
  // Beyond the middle leg's line lies the side the corners turn away from.
  const Point2 outwards = corners_turn > 0.0 ? Point2(d2.y(), -d2.x()) : Point2(-d2.y(), d2.x());
  double turning = 0.0;
  double farthest_out = -std::numeric_limits<double>::infinity();
  int straight_runs = 0;
  for (std::size_t k = 0; k < turn.arcs.size(); ++k) {
    const PathPrimitive& piece = turn.arcs[k];
    EXPECT_EQ(piece.variant(), SmoothingVariant::kBulb);
    if (piece.kind() == PrimitiveKind::kSegment) {
      ++straight_runs;
    } else {
      ASSERT_EQ(piece.kind(), PrimitiveKind::kArc);
      EXPECT_NEAR(piece.radius(), radius, 1e-12 * radius);
      turning += piece.sweep();
    }
    for (int s = 0; s <= 64; ++s) {
      farthest_out = std::max(farthest_out, (piece.poseAt(s / 64.0).position() - b1).dot(outwards));
    }
    if (k == 0) continue;
    EXPECT_LE((turn.arcs[k - 1].end() - piece.start()).norm(), gap) << k;
    EXPECT_LE(testing::headingGap(turn.arcs[k - 1].endPose().yaw, piece.startPose().yaw),
              testing::kHeadingGap)
        << k;
  }
  EXPECT_LE(straight_runs, 1);
  EXPECT_NEAR(turning, corners_turn, 1e-9);
  EXPECT_NEAR(farthest_out, 0.0, gap);
}

TEST(BulbTurnSmoothing, LanesCloserThanTwoRadiiTurnThroughABulbTouchingTheLanesEnds) {
  // Up a lane, 1 m along the boundary, down the next lane; r = 1.5 needs 3 m for a
  // semicircle. The turn touching the middle of the boundary leg bulges out by r - s / 2
  // beyond both lanes.
  const Point2 a(0, -20), b1(0, 0), b2(1, 0), c(1, -20);
  const auto bulb = BulbTurnSmoothing::compute(a, b1, b2, c, 1.5, 0.5, 0.5);
  ASSERT_TRUE(bulb);
  expectBulbTurn(a, b1, b2, c, 1.5, *bulb);
  EXPECT_EQ(bulb->arcs.size(), 4u);
  EXPECT_NEAR(bulb->entry_distance, bulb->exit_distance, 1e-9);
  // The entry circle, centred r to the lane's left, touches the circle through (0.5, 0).
  EXPECT_NEAR(bulb->entry_distance, 1.5 + std::sqrt(9.0 - 4.0), 1e-9);
  double leftmost = 0.0;
  for (const PathPrimitive& arc : bulb->arcs) {
    for (int s = 0; s <= 256; ++s)
      leftmost = std::min(leftmost, arc.poseAt(s / 256.0).position().x());
  }
  EXPECT_NEAR(leftmost, 0.5 - 1.5, 1e-3);
}

TEST(BulbTurnSmoothing, ARunAlongAllOfTheMiddleLegPassesThroughBothCorners) {
  const Point2 a(0, -20), b1(0, 0), b2(2, 0), c(2, -20);
  const auto keyhole = BulbTurnSmoothing::compute(a, b1, b2, c, 1.0, 0.0, 1.0);
  ASSERT_TRUE(keyhole);
  expectBulbTurn(a, b1, b2, c, 1.0, *keyhole);
  ASSERT_EQ(keyhole->arcs.size(), 5u);
  const PathPrimitive& run = keyhole->arcs[2];
  EXPECT_EQ(run.kind(), PrimitiveKind::kSegment);
  EXPECT_NEAR((run.start() - b1).norm(), 0.0, 1e-12);
  EXPECT_NEAR((run.end() - b2).norm(), 0.0, 1e-12);
}

TEST(BulbTurnSmoothing, RandomCornerPairsTurningTheSameWay) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> heading(-M_PI, M_PI);
  std::uniform_real_distribution<double> turn(0.3, 2.6);
  std::uniform_real_distribution<double> length(0.2, 8.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int found = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const double side = unit(random) < 0.5 ? -1.0 : 1.0;
    const double h1 = heading(random);
    const double h2 = h1 + side * turn(random);
    const double h3 = h2 + side * turn(random);
    const Point2 b1(length(random), length(random));
    const Point2 a = b1 - 30.0 * Point2(std::cos(h1), std::sin(h1));
    const Point2 b2 = b1 + length(random) * Point2(std::cos(h2), std::sin(h2));
    const Point2 c = b2 + 30.0 * Point2(std::cos(h3), std::sin(h3));
    const double radius = 0.3 + 2.0 * unit(random);
    double from = unit(random);
    double to = unit(random);
    if (from > to) std::swap(from, to);
    const auto bulb = BulbTurnSmoothing::compute(a, b1, b2, c, radius, from, to);
    if (!bulb) continue;
    ++found;
    expectBulbTurn(a, b1, b2, c, radius, *bulb);
    if (::testing::Test::HasFailure()) {
      ADD_FAILURE() << "trial " << trial;
      return;
    }
  }
  EXPECT_GT(found, 200);
}

TEST(BulbTurnSmoothing, RefusesCornersTurningOppositeWaysAndBadArguments) {
  EXPECT_FALSE(BulbTurnSmoothing::compute({0, 0}, {20, 0}, {20, 1}, {40, 1}, 1.0, 0.5, 0.5));
  EXPECT_FALSE(BulbTurnSmoothing::compute({0, -20}, {0, 0}, {1, 0}, {1, -20}, 1.0, 0.7, 0.3));
  EXPECT_FALSE(BulbTurnSmoothing::compute({0, -20}, {0, 0}, {1, 0}, {1, -20}, 0.0, 0.5, 0.5));
  EXPECT_FALSE(
      BulbTurnSmoothing::compute({0, -20}, {0, 0}, {0, 0}, {1, -20}, 1.0, 0.5, 0.5));  // no leg
  EXPECT_FALSE(
      BulbTurnSmoothing::compute({0, -20}, {0, 0}, {1, 0}, {1, -20}, std::nan(""), 0.5, 0.5));
}

}  // namespace
}  // namespace kinematic_coverage::core
