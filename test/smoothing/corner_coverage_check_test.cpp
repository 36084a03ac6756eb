#include "trajectory_generation_tools/smoothing/corner_coverage_check.h"

#include <gtest/gtest.h>

#include <cmath>

#include "trajectory_generation_tools/smoothing/path_smoother.h"

namespace kinematic_coverage::core {
namespace {

/// The one smoothed corner of a three-waypoint path, as a CornerSmoothing at `b`.
CornerSmoothing onlySmoothing(const SmoothedPath& path, const Point2& b) {
  CornerSmoothing smoothing;
  for (const PathPrimitive& p : path.primitives) {
    if (p.kind() != PrimitiveKind::kArc) continue;
    smoothing.variant = p.variant();
    smoothing.arcs.push_back(p);
  }
  if (smoothing.arcs.empty()) return smoothing;
  smoothing.entry_distance = (smoothing.arcs.front().start() - b).norm();
  smoothing.exit_distance = (smoothing.arcs.back().end() - b).norm();
  return smoothing;
}

TEST(CornerCoverageCheck, AcuteInnerArcLosesTheTipAndAGentleTurnLosesNothing) {
  const BoundaryEdgeIndex index(PolygonWithHoles{});
  const CornerCoverageCheck check(index, FrustumSensor(4.0, 3.0, 0.0));
  // 150 degree turn with an inner arc of r = 2: the tip beyond the arc goes unseen.
  const Point2 a(0, 0), b(30, 0), c(30 - 30 * std::cos(M_PI / 6), 30 * std::sin(M_PI / 6));
  const CornerSmoothing acute_smoothing =
      onlySmoothing(PathSmoother({}, 2.0).smooth(std::vector<Point2>{a, b, c}), b);
  ASSERT_EQ(acute_smoothing.arcs.size(), 1u);
  const double lost = check.lostArea({a, b, c}, acute_smoothing);
  EXPECT_GT(lost, 1.0);  // m^2: the tip of a 4 m wide footprint beyond a 2 m arc
  EXPECT_FALSE(check.preserves({a, b, c}, acute_smoothing));

  // A 10 degree turn with r = 1: the arc stays within a few centimetres of the corner.
  const Point2 d(60, 0), e(90, 30 * std::tan(M_PI / 18));
  const CornerSmoothing gentle_smoothing =
      onlySmoothing(PathSmoother({}, 1.0).smooth(std::vector<Point2>{b, d, e}), d);
  ASSERT_EQ(gentle_smoothing.arcs.size(), 1u);
  EXPECT_TRUE(check.preserves({b, d, e}, gentle_smoothing));
  EXPECT_LT(check.lostArea({b, d, e}, gentle_smoothing), lost);
}

TEST(CornerCoverageCheck, AFootprintFarShorterThanTheCornerIsMeasuredOnTheBoundedRaster) {
  // Found by corner_smoothing_fuzzer: a footprint 1 nm long (a tiny onward_fov is valid)
  // made the arcs' sampling step a fraction of a nanometre, 10^11 samples, and the sample
  // count overflowed an int. The arcs are now sampled by angle, at a step that the raster's
  // own (size-limited) cell bounds; the footprint is then as good as a line.
  const BoundaryEdgeIndex index(PolygonWithHoles{});
  const Point2 a(0, 0), b(30, 0), c(30 - 30 * std::cos(M_PI / 6), 30 * std::sin(M_PI / 6));
  const CornerSmoothing smoothing =
      onlySmoothing(PathSmoother({}, 2.0).smooth(std::vector<Point2>{a, b, c}), b);
  ASSERT_EQ(smoothing.arcs.size(), 1u);
  const double short_lost =
      CornerCoverageCheck(index, FrustumSensor(4.0, 1e-9, 0.0)).lostArea({a, b, c}, smoothing);
  const double line_lost =
      CornerCoverageCheck(index, FrustumSensor(4.0, 0.0, 0.0)).lostArea({a, b, c}, smoothing);
  EXPECT_GT(line_lost, 1.0);
  EXPECT_NEAR(short_lost, line_lost, 0.05 * line_lost);
}

}  // namespace
}  // namespace kinematic_coverage::core
