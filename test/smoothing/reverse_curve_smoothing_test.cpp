#include "trajectory_generation_tools/smoothing/reverse_curve_smoothing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "test/smoothing/smoothing_oracle.h"

namespace kinematic_coverage::core {
namespace {

/// Expects the curve to leave [a, b1] with its heading, join [b2, c] with its heading,
/// consist of two tangent arcs of `radius` turning opposite ways, and report where it
/// touches the legs.
void expectReverseCurve(const Point2& a, const Point2& b1, const Point2& b2, const Point2& c,
                        double radius, const CornerSmoothing& curve) {
  const double gap = testing::kRelativeGap *
                     std::max({(a - b1).norm(), (c - b2).norm(), radius, b1.norm(), b2.norm()});
  ASSERT_EQ(curve.arcs.size(), 2u);
  EXPECT_EQ(curve.corners, 2);
  EXPECT_EQ(curve.variant, SmoothingVariant::kReverseCurve);
  const PathPrimitive& first = curve.arcs.front();
  const PathPrimitive& second = curve.arcs.back();
  EXPECT_LE(distanceToSegment(first.start(), a, b1), gap);
  EXPECT_LE(testing::headingGap(first.startPose().yaw, headingOf(a, b1)), testing::kHeadingGap);
  EXPECT_LE(distanceToSegment(second.end(), b2, c), gap);
  EXPECT_LE(testing::headingGap(second.endPose().yaw, headingOf(b2, c)), testing::kHeadingGap);
  EXPECT_LE((first.end() - second.start()).norm(), gap);
  EXPECT_LE(testing::headingGap(first.endPose().yaw, second.startPose().yaw), testing::kHeadingGap);
  EXPECT_LT(first.sweep() * second.sweep(), 0.0);  // opposite turns
  for (const PathPrimitive& arc : curve.arcs) {
    EXPECT_NEAR(arc.radius(), radius, 1e-12 * radius);
    EXPECT_LT(std::abs(arc.sweep()), M_PI);
  }
  EXPECT_NEAR((first.start() - b1).norm(), curve.entry_distance, gap);
  EXPECT_NEAR((second.end() - b2).norm(), curve.exit_distance, gap);
}

TEST(ReverseCurveSmoothing, LaneChangeJogIsOneSCurve) {
  // Left by 90 degrees, 1 m across, right by 90 degrees: two inner smoothings of r = 1
  // would need a 2 m middle leg.
  const Point2 a(0, 0), b1(20, 0), b2(20, 1), c(40, 1);
  const auto curve = ReverseCurveSmoothing::compute(a, b1, b2, c, 1.0);
  ASSERT_TRUE(curve);
  expectReverseCurve(a, b1, b2, c, 1.0, *curve);
  // Symmetric jog: the inflection is the middle leg's midpoint, the sweeps equal.
  EXPECT_NEAR((curve->arcs[0].end() - Point2(20, 0.5)).norm(), 0.0, 1e-6);
  EXPECT_NEAR(std::abs(curve->arcs[0].sweep()), std::abs(curve->arcs[1].sweep()), 1e-6);
  EXPECT_NEAR(curve->entry_distance, curve->exit_distance, 1e-6);
}

TEST(ReverseCurveSmoothing, RefusesWhatIsNoJog) {
  // Both corners turn left (a U-turn).
  EXPECT_FALSE(ReverseCurveSmoothing::compute({0, 0}, {20, 0}, {20, 1}, {0, 1}, 1.0));
  // A middle leg longer than kMaxMiddleLegRadii radii.
  const double long_leg = ReverseCurveSmoothing::kMaxMiddleLegRadii + 0.5;
  EXPECT_FALSE(
      ReverseCurveSmoothing::compute({0, 0}, {20, 0}, {20, long_leg}, {40, long_leg}, 1.0));
  // A middle leg running back (a sweep's end, 120 degree turns): the curve would skip it.
  EXPECT_FALSE(
      ReverseCurveSmoothing::compute({0, 0}, {20, 0}, {19, std::sqrt(3.0)}, {40, 1.5}, 1.0));
  // Outer legs too short for the curve's 1.32 m run along them.
  EXPECT_FALSE(ReverseCurveSmoothing::compute({19.6, 0}, {20, 0}, {20, 1}, {20.4, 1}, 1.0));
  // A short incoming leg shifts the curve along the outgoing one.
  const auto shifted = ReverseCurveSmoothing::compute({19.9, 0}, {20, 0}, {20, 1}, {40, 1}, 1.0);
  ASSERT_TRUE(shifted);
  EXPECT_LE(shifted->entry_distance, 0.1 + 1e-9);
}

TEST(ReverseCurveSmoothing, RandomJogsAreG1AndOnTheirLegs) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int found = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const double heading = 2 * M_PI * unit(rng);
    const Point2 along(std::cos(heading), std::sin(heading));
    const Point2 left(-along.y(), along.x());
    const double radius = 0.2 + 3 * unit(rng);
    const Point2 a = 100 * Point2(unit(rng) - 0.5, unit(rng) - 0.5);
    const Point2 b1 = a + (0.5 + 30 * unit(rng)) * along;
    // The middle leg turns left by 10 to 95 degrees; the last leg turns back right by 10
    // to 95 degrees.
    const double first_turn = (10 + 85 * unit(rng)) * M_PI / 180;
    const Point2 middle = std::cos(first_turn) * along + std::sin(first_turn) * left;
    const Point2 b2 = b1 + (0.1 + 4.5 * radius * unit(rng)) * middle;
    const double out_heading = heading + first_turn - (10 + 85 * unit(rng)) * M_PI / 180;
    const Point2 c =
        b2 + (0.5 + 30 * unit(rng)) * Point2(std::cos(out_heading), std::sin(out_heading));
    const auto curve = ReverseCurveSmoothing::compute(a, b1, b2, c, radius);
    SCOPED_TRACE("trial " + std::to_string(trial));
    if (!curve) continue;
    ++found;
    expectReverseCurve(a, b1, b2, c, radius, *curve);
    EXPECT_LE(curve->entry_distance, (b1 - a).norm() + 1e-9);
    EXPECT_LE(curve->exit_distance, (c - b2).norm() + 1e-9);
    if (::testing::Test::HasFailure()) return;
  }
  EXPECT_GT(found, 500);
}

}  // namespace
}  // namespace kinematic_coverage::core
