#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <random>

#include "test/smoothing/smoothing_oracle.h"
#include "trajectory_generation_tools/smoothing/boundary_edge_index.h"
#include "trajectory_generation_tools/smoothing/corner_geometry.h"
#include "trajectory_generation_tools/smoothing/corner_smoother.h"
#include "trajectory_generation_tools/smoothing/inner_smoothing.h"
#include "trajectory_generation_tools/smoothing/outer_smoothing_bisector.h"
#include "trajectory_generation_tools/smoothing/outer_smoothing_tangent.h"

namespace kinematic_coverage::core {
namespace {

using testing::expectG1OnLegs;
using testing::judge;
using testing::Verdict;

/// A corner turning by `turn` (signed, rad) at B with legs of the given lengths, arriving
/// along the heading `heading`.
Corner makeCorner(const Point2& b, double heading, double turn, double length_in, double length_out,
                  double r) {
  const Point2 in(std::cos(heading), std::sin(heading));
  const Point2 out(std::cos(heading + turn), std::sin(heading + turn));
  return {b - length_in * in, b, b + length_out * out, r};
}

/// An axis-aligned square obstacle (clockwise, as holes are).
Ring squareHole(const Point2& centre, double half) {
  return {centre + Point2(-half, -half), centre + Point2(-half, half), centre + Point2(half, half),
          centre + Point2(half, -half)};
}

/// A counter-clockwise square hull.
Ring squareHull(const Point2& centre, double half) {
  return {centre + Point2(-half, -half), centre + Point2(half, -half), centre + Point2(half, half),
          centre + Point2(-half, half)};
}

std::optional<CornerSmoothing> smoothIn(const PolygonWithHoles& area, const Corner& corner) {
  const BoundaryEdgeIndex index(area);
  return CornerSmoother(index).smooth(corner);
}

// A left right-angle corner at the origin: in along +x, out along +y.
const Corner kRightAngle{{-10, 0}, {0, 0}, {0, 10}, 1.0};

TEST(InnerSmoothing, RightAngleIsAQuarterCircleTangentAtDistanceR) {
  const std::optional<CornerSmoothing> inner = InnerSmoothing::compute(kRightAngle);
  ASSERT_TRUE(inner);
  ASSERT_EQ(inner->arcs.size(), 1u);
  const PathPrimitive& arc = inner->arcs[0];
  EXPECT_TRUE(arc.centre().isApprox(Point2(-1, 1), 1e-14));
  EXPECT_NEAR(arc.sweep(), M_PI / 2, 1e-14);  // counter-clockwise for a left turn
  EXPECT_NEAR(inner->entry_distance, 1.0, 1e-14);
  EXPECT_NEAR(inner->exit_distance, 1.0, 1e-14);
  expectG1OnLegs(kRightAngle, *inner);
}

TEST(InnerSmoothing, RightTurnIsClockwiseAndTangentAtRoverTanHalfAngle) {
  const Corner corner = makeCorner({3, -2}, 0.4, -2.0, 20, 20, 1.5);
  const std::optional<CornerSmoothing> inner = InnerSmoothing::compute(corner);
  ASSERT_TRUE(inner);
  EXPECT_NEAR(inner->arcs[0].sweep(), -2.0, 1e-12);
  const double interior = M_PI - 2.0;
  EXPECT_NEAR(inner->entry_distance, 1.5 / std::tan(interior / 2), 1e-12);
  expectG1OnLegs(corner, *inner);
}

TEST(OuterSmoothingBisector, MiddleCirclePassesThroughBAndOuterCirclesTouchIt) {
  const std::optional<CornerSmoothing> outer = OuterSmoothingBisector::compute(kRightAngle);
  ASSERT_TRUE(outer);
  ASSERT_EQ(outer->arcs.size(), 3u);
  const std::array<Point2, 3> centres{outer->arcs[0].centre(), outer->arcs[1].centre(),
                                      outer->arcs[2].centre()};
  EXPECT_NEAR(centres[1].norm(), 1.0, 1e-14);  // |BO2| = r (Eq. 3.3)
  EXPECT_NEAR((centres[0] - centres[1]).norm(), 2.0, 1e-13);
  EXPECT_NEAR((centres[2] - centres[1]).norm(), 2.0, 1e-13);
  EXPECT_NEAR(std::abs(centres[2].x()), 1.0, 1e-13);  // dist(BC, O3) = r, outer side
  EXPECT_GT(centres[2].x(), 0.0);
  EXPECT_LT(centres[0].y(), 0.0);
  // Turns: against, with, against the corner; headings add up to the corner's turn.
  EXPECT_LT(outer->arcs[0].sweep(), 0.0);
  EXPECT_GT(outer->arcs[1].sweep(), 0.0);
  EXPECT_LT(outer->arcs[2].sweep(), 0.0);
  EXPECT_NEAR(outer->arcs[0].sweep() + outer->arcs[1].sweep() + outer->arcs[2].sweep(), M_PI / 2,
              1e-13);
  // Tangent points at r (cos(alpha) + sqrt(4 - (1 + sin(alpha))^2)) from B, alpha = pi/4.
  const double s = std::sqrt(0.5);
  EXPECT_NEAR(outer->entry_distance, s + std::sqrt(4 - (1 + s) * (1 + s)), 1e-13);
  EXPECT_NEAR(outer->exit_distance, outer->entry_distance, 1e-13);
  expectG1OnLegs(kRightAngle, *outer);
}

TEST(OuterSmoothingTangent, ShorterLegEndsAtItsWaypoint) {
  // |BC| = 1.2 < |AB|: the last circle touches BC at C (Alg. 8's else branch).
  const Corner corner{{-10, 0}, {0, 0}, {0, 1.2}, 1.0};
  const std::optional<CornerSmoothing> outer = OuterSmoothingTangent::compute(corner);
  ASSERT_TRUE(outer);
  EXPECT_NEAR(outer->exit_distance, 1.2, 1e-14);
  EXPECT_NEAR(outer->entry_distance, 1.2, 1e-13);
  EXPECT_TRUE(outer->arcs.back().end().isApprox(corner.c, 1e-13));
  const double spread = (outer->arcs[0].centre() - outer->arcs[2].centre()).norm();
  EXPECT_GT(spread, 2.0);
  EXPECT_LT(spread, 4.0);
  expectG1OnLegs(corner, *outer);
  // Mirror case: the shorter leg is AB, so the first arc starts at A.
  const Corner mirrored{{-1.2, 0}, {0, 0}, {0, 10}, 1.0};
  const std::optional<CornerSmoothing> other = OuterSmoothingTangent::compute(mirrored);
  ASSERT_TRUE(other);
  EXPECT_TRUE(other->arcs.front().start().isApprox(mirrored.a, 1e-13));
  expectG1OnLegs(mirrored, *other);
}

TEST(OuterSmoothingTangent, RejectsCirclesThatOverlapOrAreTooFarApart) {
  // Legs of 0.2 r: the outer circles overlap; legs of 10 r: too far for the middle one.
  EXPECT_FALSE(OuterSmoothingTangent::compute({{-0.2, 0}, {0, 0}, {0, 0.2}, 1.0}));
  EXPECT_FALSE(OuterSmoothingTangent::compute({{-10, 0}, {0, 0}, {0, 10}, 1.0}));
}

TEST(CornerSmoothingDegenerate, CollinearCornersAreNoTurn) {
  const Corner straight{{-5, 0}, {0, 0}, {7, 0}, 1.0};
  EXPECT_TRUE(CornerGeometry::of(straight)->isStraight());
  EXPECT_FALSE(InnerSmoothing::compute(straight));
  EXPECT_FALSE(OuterSmoothingBisector::compute(straight));
  EXPECT_FALSE(OuterSmoothingTangent::compute(straight));
  EXPECT_FALSE(smoothIn({}, straight));
}

TEST(CornerSmoothingDegenerate, DuplicatePointsGiveNoCorner) {
  const Corner same_bc{{-5, 0}, {0, 0}, {0, 0}, 1.0};
  EXPECT_FALSE(CornerGeometry::of(same_bc));
  EXPECT_FALSE(InnerSmoothing::compute(same_bc));
  EXPECT_FALSE(smoothIn({}, same_bc));
  // A == B needs the incoming direction; with it the corner is well defined.
  const Corner same_ab{{0, 0}, {0, 0}, {0, 5}, 1.0};
  EXPECT_FALSE(CornerGeometry::of(same_ab));
  Corner with_direction = same_ab;
  with_direction.incoming = Point2(1, 0);
  ASSERT_TRUE(CornerGeometry::of(with_direction));
  EXPECT_NEAR(CornerGeometry::of(with_direction)->turn(), M_PI / 2, 1e-15);
  // The inner arc exists but cannot start before A == B; the outer circles overlap.
  const std::optional<CornerSmoothing> inner = InnerSmoothing::compute(with_direction);
  ASSERT_TRUE(inner);
  EXPECT_GT(inner->entry_distance, 0.0);
  EXPECT_FALSE(smoothIn({}, with_direction));
}

TEST(CornerSmoothingDegenerate, NonFiniteInputGivesNothing) {
  const double nan = std::nan("");
  EXPECT_FALSE(InnerSmoothing::compute({{nan, 0}, {0, 0}, {0, 5}, 1.0}));
  EXPECT_FALSE(OuterSmoothingBisector::compute({{-5, 0}, {0, 0}, {0, 5}, nan}));
  EXPECT_FALSE(OuterSmoothingTangent::compute({{-5, 0}, {0, 0}, {0, 5}, -1.0}));
}

TEST(CornerSmoothingDegenerate, InteriorAngleNearZeroUsesTheOuterLoop) {
  for (const double gap : {0.0, 1e-12, 1e-8, 1e-3}) {
    const Corner corner = makeCorner({1, 2}, 0.3, M_PI - gap, 30, 30, 1.0);
    // Inner smoothing is either refused (a reversal) or needs legs far longer than 30 r.
    const std::optional<CornerSmoothing> inner = InnerSmoothing::compute(corner);
    EXPECT_TRUE(!inner || inner->entry_distance > 30) << gap;
    const std::optional<CornerSmoothing> smoothing = smoothIn({}, corner);
    ASSERT_TRUE(smoothing) << gap;
    EXPECT_EQ(smoothing->variant, SmoothingVariant::kOuterBisector);
    expectG1OnLegs(corner, *smoothing);
  }
}

TEST(CornerSmoothingDegenerate, InteriorAngleNearPiIsATinyInnerArc) {
  for (const double turn : {2e-9, 1e-7, 1e-4}) {
    const Corner corner = makeCorner({50, -20}, 2.0, -turn, 5, 5, 2.0);
    const std::optional<CornerSmoothing> smoothing = smoothIn({}, corner);
    ASSERT_TRUE(smoothing) << turn;
    EXPECT_EQ(smoothing->variant, SmoothingVariant::kInner);
    EXPECT_NEAR(smoothing->arcs[0].sweep(), -turn, 1e-15);
    EXPECT_NEAR(smoothing->entry_distance, 2.0 * std::tan(turn / 2), 1e-12);
    expectG1OnLegs(corner, *smoothing);
  }
}

TEST(CornerSmoothingDegenerate, LegShorterThanTheInnerTangentDistance) {
  // Interior angle 60 degrees: inner needs r / tan(30 deg) = 1.73 r, the bisector variant
  // 2.24 r; a 1.6 r leg fits neither, so the tangent-intersection variant is used.
  const Corner corner = makeCorner({0, 0}, 0.0, 2 * M_PI / 3, 1.6, 10, 1.0);
  const std::optional<CornerSmoothing> inner = InnerSmoothing::compute(corner);
  ASSERT_TRUE(inner);
  EXPECT_NEAR(inner->entry_distance, 1.0 / std::tan(M_PI / 6), 1e-12);
  const std::optional<CornerSmoothing> smoothing = smoothIn({}, corner);
  ASSERT_TRUE(smoothing);
  EXPECT_EQ(smoothing->variant, SmoothingVariant::kOuterTangent);
  EXPECT_TRUE(smoothing->arcs.front().start().isApprox(corner.a, 1e-12));
  expectG1OnLegs(corner, *smoothing);
  // Legs shorter still (0.2 r): the outer circles would overlap; the corner stays sharp.
  EXPECT_FALSE(smoothIn({}, makeCorner({0, 0}, 0.0, 2 * M_PI / 3, 0.2, 0.2, 1.0)));
}

TEST(CornerSmoothingDegenerate, LegsBetweenRAndTwoR) {
  // Right angle, legs 1.5 r: inner fits (needs r); the bisector variant does not (1.75 r).
  const Corner corner{{-1.5, 0}, {0, 0}, {0, 1.5}, 1.0};
  const std::optional<CornerSmoothing> free_smoothing = smoothIn({}, corner);
  ASSERT_TRUE(free_smoothing);
  EXPECT_EQ(free_smoothing->variant, SmoothingVariant::kInner);
  expectG1OnLegs(corner, *free_smoothing);
  // With an obstacle on the inner side, the tangent-intersection variant remains.
  PolygonWithHoles area;
  area.holes.push_back(squareHole({-0.45, 0.45}, 0.2));
  const std::optional<CornerSmoothing> blocked = smoothIn(area, corner);
  ASSERT_TRUE(blocked);
  EXPECT_EQ(blocked->variant, SmoothingVariant::kOuterTangent);
  expectG1OnLegs(corner, *blocked);
  EXPECT_EQ(judge(area, corner, blocked), Verdict::kFree);
}

TEST(CornerSmoothingVariants, ObstacleOnTheInnerSideForcesOuterSmoothing) {
  PolygonWithHoles area;
  area.hull = squareHull({0, 0}, 50);
  area.holes.push_back(squareHole({-0.45, 0.45}, 0.2));
  const std::optional<CornerSmoothing> inner = InnerSmoothing::compute(kRightAngle);
  EXPECT_EQ(judge(area, kRightAngle, inner), Verdict::kInfeasible);
  const std::optional<CornerSmoothing> smoothing = smoothIn(area, kRightAngle);
  ASSERT_TRUE(smoothing);
  EXPECT_EQ(smoothing->variant, SmoothingVariant::kOuterBisector);
  EXPECT_EQ(judge(area, kRightAngle, smoothing), Verdict::kFree);
  expectG1OnLegs(kRightAngle, *smoothing);
}

TEST(CornerSmoothingVariants, ObstaclesOnBothSidesBlockEveryVariant) {
  PolygonWithHoles area;
  area.hull = squareHull({0, 0}, 50);
  area.holes.push_back(squareHole({-0.25, 0.25}, 0.1));  // inner side, on the inner arc
  area.holes.push_back(squareHole({-0.7, -0.45}, 0.2));  // outer side, below AB near B
  for (const Corner& corner : {kRightAngle, Corner{{-1.5, 0}, {0, 0}, {0, 1.5}, 1.0}}) {
    EXPECT_EQ(judge(area, corner, InnerSmoothing::compute(corner)), Verdict::kInfeasible);
    EXPECT_EQ(judge(area, corner, OuterSmoothingBisector::compute(corner)), Verdict::kInfeasible);
    EXPECT_EQ(judge(area, corner, OuterSmoothingTangent::compute(corner)), Verdict::kInfeasible);
    EXPECT_FALSE(smoothIn(area, corner));
  }
}

TEST(CornerSmoothingVariants, TiesOfLegLengthsAreDeterministic) {
  const Corner corner{{-1.3, 0}, {0, 0}, {0, 1.3}, 1.0};
  const std::optional<CornerSmoothing> first = OuterSmoothingTangent::compute(corner);
  const std::optional<CornerSmoothing> second = OuterSmoothingTangent::compute(corner);
  ASSERT_TRUE(first && second);
  // The else branch of Alg. 8: C's circle first, so the last arc ends exactly at C.
  EXPECT_TRUE(first->arcs.back().end().isApprox(corner.c, 1e-14));
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(first->arcs[i].centre(), second->arcs[i].centre());
    EXPECT_EQ(first->arcs[i].sweep(), second->arcs[i].sweep());
  }
  expectG1OnLegs(corner, *first);
}

TEST(CornerSmoothingFeasibility, SmoothingMayNotStartBeforeA) {
  // A is the end of a previous smoothing 0.5 r before B: inner (needs r) would overlap it.
  const Corner corner{{-0.5, 0}, {0, 0}, {0, 10}, 1.0};
  const BoundaryEdgeIndex index(PolygonWithHoles{});
  const CornerSmoother smoother(index);
  EXPECT_FALSE(smoother.feasible(corner, *InnerSmoothing::compute(corner)));
  const std::optional<CornerSmoothing> smoothing = smoother.smooth(corner);
  ASSERT_TRUE(smoothing);
  EXPECT_GE(smoothing->entry_distance, 0.0);
  EXPECT_LE(smoothing->entry_distance, 0.5 + 1e-12);
}

TEST(CornerSmoothingFeasibility, JoiningSegmentsAndStartMustBeFree) {
  PolygonWithHoles area;
  area.hull = squareHull({0, 0}, 50);
  // An obstacle across the incoming leg far from B blocks the joining segment [A, I1].
  area.holes.push_back(squareHole({-6, 0}, 0.5));
  EXPECT_FALSE(smoothIn(area, kRightAngle));
  // A outside the hull: nothing is feasible.
  PolygonWithHoles small;
  small.hull = squareHull({0, 0}, 5);
  EXPECT_FALSE(smoothIn(small, kRightAngle));
}

/// One random corner with random obstacles near B (the property test's generator).
struct RandomCorner {
  Corner corner;
  PolygonWithHoles area;
};

RandomCorner randomCorner(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto log_uniform = [&](double low, double high) {
    return std::exp(std::log(low) + unit(rng) * (std::log(high) - std::log(low)));
  };
  RandomCorner sample;
  const double r = log_uniform(0.1, 10.0);
  const Point2 b(200 * unit(rng) - 100, 200 * unit(rng) - 100);
  const double heading = 2 * M_PI * unit(rng) - M_PI;
  const double kind = unit(rng);
  double turn = M_PI * unit(rng);
  if (kind < 0.1) turn = log_uniform(1e-10, 1e-3);
  if (kind > 0.9) turn = M_PI - log_uniform(1e-13, 1e-3);
  if (unit(rng) < 0.5) turn = -turn;
  sample.corner =
      makeCorner(b, heading, turn, r * log_uniform(0.1, 20.0), r * log_uniform(0.1, 20.0), r);
  const double hull_half = r * log_uniform(3.0, 60.0);
  sample.area.hull = squareHull(b + r * Point2(unit(rng) - 0.5, unit(rng) - 0.5), hull_half);
  const int obstacles = static_cast<int>(4 * unit(rng));
  std::vector<std::pair<Point2, double>> placed;
  for (int i = 0; i < obstacles; ++i) {
    const Point2 centre = b + r * Point2(6 * unit(rng) - 3, 6 * unit(rng) - 3);
    const double half_w = r * log_uniform(0.02, 1.0);
    const double half_h = r * log_uniform(0.02, 1.0);
    const double circumradius = std::hypot(half_w, half_h);
    bool overlaps = false;
    for (const auto& [other, other_radius] : placed) {
      overlaps = overlaps || (other - centre).norm() <= circumradius + other_radius;
    }
    if (overlaps) continue;
    placed.push_back({centre, circumradius});
    const double angle = M_PI * unit(rng);
    const Point2 x(std::cos(angle), std::sin(angle));
    const Point2 y(-x.y(), x.x());
    // Clockwise: -x-y, -x+y, +x+y, +x-y.
    sample.area.holes.push_back({centre - half_w * x - half_h * y, centre - half_w * x + half_h * y,
                                 centre + half_w * x + half_h * y,
                                 centre + half_w * x - half_h * y});
  }
  return sample;
}

TEST(CornerSmoothingProperties, HundredThousandRandomCorners) {
  std::mt19937_64 rng(20240611);
  constexpr int kCorners = 100000;
  std::array<int, 4> used{};  // kNone (sharp), inner, bisector, tangent
  int undecided = 0;
  for (int i = 0; i < kCorners; ++i) {
    const RandomCorner sample = randomCorner(rng);
    const Corner& corner = sample.corner;
    const BoundaryEdgeIndex index(sample.area);
    const std::optional<CornerSmoothing> chosen = CornerSmoother(index).smooth(corner);
    const std::array<std::optional<CornerSmoothing>, 3> variants{
        InnerSmoothing::compute(corner), OuterSmoothingBisector::compute(corner),
        OuterSmoothingTangent::compute(corner)};
    for (const auto& variant : variants) {
      if (variant) ASSERT_TRUE(testing::allFinite(*variant)) << "corner " << i;
    }
    const int chosen_rank = chosen ? static_cast<int>(chosen->variant) : 4;
    ++used[chosen ? static_cast<int>(chosen->variant) : 0];
    if (chosen) {
      SCOPED_TRACE("corner " + std::to_string(i));
      expectG1OnLegs(corner, *chosen);
      const Verdict verdict = judge(sample.area, corner, chosen);
      ASSERT_NE(verdict, Verdict::kInfeasible) << "corner " << i;
      // The module's arcs and variant functions agree.
      const auto& same = variants[chosen_rank - 1];
      ASSERT_TRUE(same);
      ASSERT_EQ(same->arcs.size(), chosen->arcs.size());
    }
    // Every variant before the chosen one (all three when none is) is infeasible.
    for (int rank = 1; rank < chosen_rank; ++rank) {
      const Verdict verdict = judge(sample.area, corner, variants[rank - 1]);
      ASSERT_NE(verdict, Verdict::kFree) << "corner " << i << " variant " << rank;
      if (verdict == Verdict::kUndecided) ++undecided;
    }
    if (::testing::Test::HasFailure()) FAIL() << "corner " << i;
  }
  // Every outcome occurs often, and the oracle could decide nearly every rejection.
  for (const int count : used) EXPECT_GT(count, kCorners / 100);
  EXPECT_LT(undecided, kCorners / 100);
  std::printf("sharp %d inner %d outer_bisector %d outer_tangent %d undecided %d\n", used[0],
              used[1], used[2], used[3], undecided);
}

}  // namespace
}  // namespace kinematic_coverage::core
