#include "trajectory_generation_tools/smoothing/global_path_smoother.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/sweeps/seen_area.h"
#include "test/smoothing/smoothing_oracle.h"
#include "trajectory_generation_tools/smoothing/corner_coverage_check.h"

namespace kinematic_coverage::core {
namespace {

GlobalSmoothingOptions options(double radius, double min_radius) {
  GlobalSmoothingOptions result;
  result.vehicle.turning_radius = radius;
  result.min_turning_radius = min_radius;
  return result;
}

/// Boustrophedon lanes `spacing` apart, 40 m long, in a hull with 5 m of margin.
std::vector<Point2> lanes(int count, double spacing) {
  std::vector<Point2> points;
  for (int i = 0; i < count; ++i) {
    points.push_back({spacing * i, i % 2 == 0 ? 0.0 : 40.0});
    points.push_back({spacing * i, i % 2 == 0 ? 40.0 : 0.0});
  }
  return points;
}

PolygonWithHoles lanesHull(int count, double spacing) {
  PolygonWithHoles area;
  area.hull = {{-5, -5}, {spacing * count + 5, -5}, {spacing * count + 5, 45}, {-5, 45}};
  return area;
}

TEST(GlobalPathSmoother, RejectsInvalidOptions) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(GlobalPathSmoother({}, options(0.0, 0.0)), InvalidInputError);
  EXPECT_THROW(GlobalPathSmoother({}, options(1.0, 2.0)), InvalidInputError);
  EXPECT_THROW(GlobalPathSmoother({}, options(1.0, nan)), InvalidInputError);
  EXPECT_THROW(GlobalPathSmoother({}, options(1.0, -0.5)), InvalidInputError);
  GlobalSmoothingOptions slow = options(1.0, 1.0);
  slow.vehicle.a_max = 0.0;
  EXPECT_THROW(GlobalPathSmoother({}, slow), InvalidInputError);
  for (const double wider : {nan, -1.0, std::numeric_limits<double>::infinity()}) {
    GlobalSmoothingOptions bad = options(1.0, 1.0);
    bad.max_turning_radius = wider;
    EXPECT_THROW(GlobalPathSmoother({}, bad), InvalidInputError);
  }
  const GlobalPathSmoother smoother({}, options(1.0, 1.0));
  EXPECT_THROW(smoother.smooth(std::vector<Point2>{{0, 0}, {nan, 1}}), InvalidInputError);
}

TEST(GlobalPathSmoother, DegeneratePathsGiveWhatLocalGives) {
  const GlobalPathSmoother smoother({}, options(1.0, 1.0));
  EXPECT_TRUE(smoother.smooth(std::vector<Point2>{}).primitives.empty());
  EXPECT_TRUE(smoother.smooth(std::vector<Point2>{{1, 1}, {1, 1}}).primitives.empty());
  const SmoothedPath straight =
      smoother.smooth(std::vector<Point2>{{0, 0}, {1, 1}, {2, 2}, {2, 2}, {5, 5}});
  ASSERT_EQ(straight.primitives.size(), 1u);
  EXPECT_EQ(straight.statistics.turns_total, 0);
  // A reversal and legs far shorter than r.
  const SmoothedPath reversal = smoother.smooth(
      std::vector<Point2>{{0, 0}, {10, 0}, {0, 0}, {0, 0.2}, {0.2, 0.2}, {0.2, 0.4}, {5, 5}});
  testing::expectContinuousPath(reversal, 10.0);
  EXPECT_EQ(reversal.statistics.turns_total, 5);
}

TEST(GlobalPathSmoother, JogBetweenLanesIsAReverseCurve) {
  // The lake mission's lane extension: left, 1 m across, right, with r = 1.
  const std::vector<Point2> jog{{0, 0}, {20, 0}, {20, 1}, {40, 1}};
  const SmoothedPath global = GlobalPathSmoother({}, options(1.0, 1.0)).smooth(jog);
  testing::expectContinuousPath(global, 40.0);
  EXPECT_EQ(global.statistics.turns_total, 2);
  EXPECT_EQ(global.statistics.turns_smoothed, 2);
  EXPECT_EQ(global.statistics.reverse_curve, 2);
}

TEST(GlobalPathSmoother, SmoothsEveryTurnOfABoustrophedon) {
  const SmoothedPath path =
      GlobalPathSmoother(lanesHull(20, 2.0), options(1.0, 1.0)).smooth(lanes(20, 2.0));
  testing::expectContinuousPath(path, 100.0);
  EXPECT_EQ(path.statistics.turns_total, 38);
  EXPECT_EQ(path.statistics.turns_smoothed, 38);
}

TEST(GlobalPathSmoother, TighterRadiusSmoothsCloselySpacedLanes) {
  // Lanes 1 m apart with r = 1.5: two inner arcs of 1.5 m do not fit in a 1 m U-turn;
  // with min_turning_radius 0.5 they do.
  const PolygonWithHoles area = lanesHull(10, 1.0);
  const std::vector<Point2> points = lanes(10, 1.0);
  const SmoothedPath fixed = GlobalPathSmoother(area, options(1.5, 1.5)).smooth(points);
  const SmoothedPath variable = GlobalPathSmoother(area, options(1.5, 0.5)).smooth(points);
  testing::expectContinuousPath(fixed, 50.0);
  testing::expectContinuousPath(variable, 50.0);
  EXPECT_EQ(variable.statistics.turns_smoothed, variable.statistics.turns_total);
  EXPECT_EQ(variable.statistics.inner, variable.statistics.turns_total);
  for (const PathPrimitive& p : variable.primitives) {
    if (p.kind() != PrimitiveKind::kArc) continue;
    EXPECT_GE(p.radius(), 0.5 - 1e-12);
    EXPECT_LE(p.radius(), 1.5 + 1e-12);
    EXPECT_GT(testing::sampledArcClearance(area, p, 0.005), 1e-9);
  }
  EXPECT_LT(fixed.statistics.inner, variable.statistics.inner);
}

TEST(GlobalPathSmoother, BulbTurnsTakeCloselySpacedLanesAtTheTurningRadius) {
  // The same lanes with bulb turns among the candidates (coverage-safe smoothing's): a
  // bulb (out beyond both lanes and back, along the boundary between them) of a larger
  // radius than inner arcs that fit, so driven faster, takes every U-turn.
  const PolygonWithHoles area = lanesHull(10, 1.0);
  const std::vector<Point2> points = lanes(10, 1.0);
  GlobalSmoothingOptions with_bulbs = options(1.5, 0.5);
  with_bulbs.bulb_turns = true;
  const SmoothedPath path = GlobalPathSmoother(area, with_bulbs).smooth(points);
  testing::expectContinuousPath(path, 50.0);
  EXPECT_EQ(path.statistics.bulb, path.statistics.turns_total);
  for (const PathPrimitive& p : path.primitives) {
    if (p.kind() != PrimitiveKind::kArc) continue;
    EXPECT_GE(p.radius(), 0.5 - 1e-12);
    EXPECT_LE(p.radius(), 1.5 + 1e-12);
    EXPECT_GT(testing::sampledArcClearance(area, p, 0.005), 1e-9);
  }
  EXPECT_LT(GlobalPathSmoother(area, with_bulbs).programme(points).plan().time,
            GlobalPathSmoother(area, options(1.5, 0.5)).programme(points).plan().time);
}

TEST(GlobalPathSmoother, CoveragePreservingKeepsAcuteInnerCornersSharp) {
  // A zigzag with acute corners and lanes one footprint apart (no overlap): inner arcs
  // cut the corners' tips, which the sharp path saw.
  const FrustumSensor sensor(4.0, 3.0, 0.0);
  PolygonWithHoles area;
  area.hull = {{-10, -10}, {50, -10}, {50, 30}, {-10, 30}};
  const std::vector<Point2> zigzag{{0, 0}, {30, 0}, {0, 4}, {30, 8}, {0, 12}};
  GlobalSmoothingOptions preserving = options(2.0, 2.0);
  preserving.preserved_sensor = sensor;
  const SmoothedPath plain = GlobalPathSmoother(area, options(2.0, 2.0)).smooth(zigzag);
  const SmoothedPath kept = GlobalPathSmoother(area, preserving).smooth(zigzag);
  testing::expectContinuousPath(kept, 50.0);
  EXPECT_GT(plain.statistics.inner, 0);
  EXPECT_EQ(kept.statistics.inner, 0);
  EXPECT_GT(kept.statistics.kept_for_coverage, 0);
  EXPECT_EQ(kept.statistics.turns_smoothed + kept.statistics.kept_for_coverage,
            kept.statistics.turns_total);
}

/// The arcs of a one-corner path at `b` as the CornerSmoothing they came from.
CornerSmoothing arcsOf(const SmoothedPath& path, const Point2& b) {
  CornerSmoothing smoothing;
  for (const PathPrimitive& p : path.primitives) {
    if (p.kind() == PrimitiveKind::kArc) smoothing.arcs.push_back(p);
  }
  if (smoothing.arcs.empty()) return smoothing;
  smoothing.entry_distance = (smoothing.arcs.front().start() - b).norm();
  smoothing.exit_distance = (smoothing.arcs.back().end() - b).norm();
  return smoothing;
}

TEST(GlobalPathSmoother, CoveragePreservingChoosesTheFastestSmoothingThatPreserves) {
  // Coverage is checked only for the smoothings the programme chooses, dropping refused
  // ones and choosing again. On seeded random corners of every angle, sensors and radii
  // (variable radius: several candidates per corner): a smoothing it keeps preserves
  // coverage, and where the unconstrained choice already preserves coverage it is kept
  // unchanged.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int smoothed = 0;
  int unconstrained_kept = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const double radius = 0.5 + 2.5 * unit(rng);
    const double width = 2.0 + 8.0 * unit(rng);
    const FrustumSensor sensor(width, (0.3 + 0.7 * unit(rng)) * width, 0.0);
    // Every other corner a gentle one, which a smoothing can take without loss.
    const double turn = M_PI * (0.02 + (trial % 2 == 0 ? 0.15 : 0.96) * unit(rng));
    const Point2 a(0, 0), b(30, 0);
    const Point2 c = b + (10 + 20 * unit(rng)) * Point2(std::cos(turn), std::sin(turn));
    GlobalSmoothingOptions preserving = options(radius, 0.3 * radius);
    preserving.preserved_sensor = sensor;
    const SmoothedPath free =
        GlobalPathSmoother({}, options(radius, 0.3 * radius)).smooth({a, b, c});
    const SmoothedPath kept = GlobalPathSmoother({}, preserving).smooth({a, b, c});
    SCOPED_TRACE("trial " + std::to_string(trial));
    testing::expectContinuousPath(kept, 60.0);
    const BoundaryEdgeIndex index(PolygonWithHoles{});
    const CornerCoverageCheck check(index, sensor);
    const CornerSmoothing kept_smoothing = arcsOf(kept, b);
    if (!kept_smoothing.arcs.empty()) {
      ++smoothed;
      EXPECT_TRUE(check.preserves({a, b, c}, kept_smoothing));
    } else {
      EXPECT_EQ(kept.statistics.kept_for_coverage, 1);
    }
    const CornerSmoothing free_smoothing = arcsOf(free, b);
    if (!free_smoothing.arcs.empty() && check.preserves({a, b, c}, free_smoothing)) {
      ++unconstrained_kept;
      ASSERT_EQ(kept.primitives.size(), free.primitives.size());
      for (std::size_t k = 0; k < kept.primitives.size(); ++k) {
        EXPECT_TRUE(kept.primitives[k].end().isApprox(free.primitives[k].end(), 1e-12));
      }
    }
  }
  // Both branches are exercised: some corners keep their fastest smoothing, and more are
  // smoothed than that (a slower smoothing that preserves coverage).
  EXPECT_GT(unconstrained_kept, 10);
  EXPECT_GT(smoothed, unconstrained_kept);
}

/// The reachable area (m^2) that the sharp path through `waypoints` sees and `path` does
/// not, on a raster of 3 cm cells over `area`, a rectangle: the cells within half a
/// footprint length of the rectangle shrunk by `wall_distance` (its offset free area).
double lostReachable(const PolygonWithHoles& area, double wall_distance,
                     const std::vector<Point2>& waypoints, const SmoothedPath& path,
                     const FrustumSensor& sensor) {
  const CoverageRaster raster = CoverageRaster::covering(area, {0.03});
  const Point2 low = area.hull[0] + Point2::Constant(wall_distance);
  const Point2 high = area.hull[2] - Point2::Constant(wall_distance);
  std::vector<Pose2> sharp_poses;
  for (const Point2& p : waypoints) sharp_poses.push_back({p.x(), p.y(), 0.0});
  SeenArea sharp(raster);
  sharp.addWaypointPath(sharp_poses, sensor, 0.05);
  std::vector<Pose2> poses;
  for (const PathPrimitive& p : path.primitives) {
    for (int k = 0; k <= 200; ++k) poses.push_back(p.poseAt(k / 200.0));
  }
  SeenArea smoothed(raster);
  smoothed.addSweptPath(poses, sensor);
  std::size_t lost = 0;
  for (std::size_t i = 0; i < raster.cellCount(); ++i) {
    if (!sharp.seen(i) || smoothed.seen(i)) continue;
    const Point2 centre = raster.cellCentre(i);
    const Point2 outside = (low - centre).cwiseMax(centre - high).cwiseMax(Point2::Zero());
    if (insideRing(centre, area.hull) && outside.norm() <= 0.5 * sensor.length()) ++lost;
  }
  return lost * raster.cellArea();
}

TEST(GlobalPathSmoother, CoverageSafeKeepsTheTipOfADeadEndBay) {
  // A bay 11 m wide, swept up one lane and back down another 3 m beside it: the turn at
  // its far end is a near-reversal, which the inner arc takes 32 m before the end. The
  // plain programme loses the bay's end; the coverage-safe one turns beyond it instead.
  const FrustumSensor sensor(4.0, 3.0, 0.0);
  PolygonWithHoles bay;
  bay.hull = {{-4, -10}, {7, -10}, {7, 43}, {-4, 43}};
  const std::vector<Point2> path{{0, -8}, {0, 40}, {3, -8}, {6, -8}};
  GlobalSmoothingOptions safe = options(1.0, 1.0);
  safe.safe_sensor = sensor;
  safe.wall_distance = 3.0;  // the lanes' ends keep 3 m from the walls
  const SmoothedPath plain = GlobalPathSmoother(bay, options(1.0, 1.0)).smooth(path);
  const SmoothedPath kept = GlobalPathSmoother(bay, safe).smooth(path);
  testing::expectContinuousPath(kept, 60.0);
  EXPECT_GT(lostReachable(bay, 3.0, path, plain, sensor), 1.0);
  EXPECT_LT(lostReachable(bay, 3.0, path, kept, sensor), 0.05);
  EXPECT_EQ(kept.statistics.inner, 1);  // the last corner, a right angle
  for (const PathPrimitive& p : kept.primitives) {
    if (p.kind() == PrimitiveKind::kArc) {
      EXPECT_GT(testing::sampledArcClearance(bay, p, 0.005), 1e-9);
    }
  }
}

TEST(GlobalPathSmoother, CoverageSafeSmoothsWhatOverlappingLanesSeeAgain) {
  // Boustrophedon lanes 2 m apart under a 4 m wide footprint: what a U-turn's arcs cut off
  // between two lanes, the neighbouring lanes see, so those turns stay smoothed. Only the
  // outermost lanes' outer corners have no neighbour beyond them: there the cut loses a
  // corner of the reachable area, which the plain programme gives up and the coverage-safe
  // one keeps.
  const FrustumSensor sensor(4.0, 3.0, 0.0);
  GlobalSmoothingOptions safe = options(1.0, 1.0);
  safe.safe_sensor = sensor;
  safe.wall_distance = 5.0;  // the lanes keep 5 m from the walls
  const PolygonWithHoles area = lanesHull(20, 2.0);
  const SmoothedPath plain = GlobalPathSmoother(area, options(1.0, 1.0)).smooth(lanes(20, 2.0));
  const SmoothedPath path = GlobalPathSmoother(area, safe).smooth(lanes(20, 2.0));
  testing::expectContinuousPath(path, 100.0);
  EXPECT_EQ(plain.statistics.turns_smoothed, 38);
  EXPECT_GE(path.statistics.turns_smoothed, 36);
  EXPECT_EQ(path.statistics.turns_smoothed + path.statistics.kept_for_coverage, 38);
  EXPECT_GT(lostReachable(area, 5.0, lanes(20, 2.0), plain, sensor), 0.5);
  EXPECT_LT(lostReachable(area, 5.0, lanes(20, 2.0), path, sensor), 0.05);
}

TEST(GlobalPathSmoother, CoverageSafeTakesAGuardedCornerByAnArcThatLosesOnlyUnreachableArea) {
  // A right angle 3 m from both walls under a 4 m x 3 m footprint: the reachable area ends
  // 1.5 m beyond the path. The widest arc (3 m) cuts into it, so the corner is guarded; a
  // tighter arc keeps every reachable cell the sharp turn sees and misses only what the
  // in-place rotation's footprint corners sweep beyond the reachable rim. Coverage-safe
  // smoothing takes that arc; the corner's own test in the free area (coverage_preserving's)
  // would have kept the corner sharp.
  const FrustumSensor sensor(4.0, 3.0, 0.0);
  PolygonWithHoles room;
  room.hull = {{-3, -3}, {23, -3}, {23, 23}, {-3, 23}};
  const std::vector<Point2> corner{{0, 0}, {20, 0}, {20, 20}};
  GlobalSmoothingOptions safe = options(3.0, 0.5);
  safe.safe_sensor = sensor;
  safe.wall_distance = 3.0;
  const SmoothedPath plain = GlobalPathSmoother(room, options(3.0, 0.5)).smooth(corner);
  const SmoothedPath path = GlobalPathSmoother(room, safe).smooth(corner);
  testing::expectContinuousPath(path, 40.0);
  EXPECT_GT(lostReachable(room, 3.0, corner, plain, sensor), 0.05);
  EXPECT_LT(lostReachable(room, 3.0, corner, path, sensor), 0.05);
  ASSERT_EQ(path.statistics.inner, 1);
  EXPECT_EQ(path.statistics.kept_for_coverage, 0);
  CornerSmoothing taken;
  for (const PathPrimitive& p : path.primitives) {
    if (p.kind() == PrimitiveKind::kArc) taken.arcs.push_back(p);
  }
  ASSERT_EQ(taken.arcs.size(), 1u);
  const double radius = taken.arcs.front().radius();
  EXPECT_LT(radius, 3.0);
  taken.entry_distance = radius;  // a right angle's inner arc starts r before the corner
  taken.exit_distance = radius;
  const BoundaryEdgeIndex index(room);
  EXPECT_FALSE(CornerCoverageCheck(index, sensor).preserves(corner, taken));
}

TEST(GlobalPathSmoother, CoverageSafeTakesTurnsAtTheWiderRadiusWhereTheTightOneCrawls) {
  // Lanes 2 m apart under a 4 m wide footprint, a robot that turns as tight as 0.3 m but
  // drives an arc at yaw_rate_max * radius: 0.15 m/s at 0.3 m. With max_turning_radius
  // 1 m (v_max / yaw_rate_max, the globalSmoothingOptionsOf default) every U-turn is a half
  // circle at full speed, which the neighbouring lanes' footprints see round; the path is
  // faster and sees what the sharp path sees.
  const FrustumSensor sensor(4.0, 3.0, 0.0);
  GlobalSmoothingOptions tight = options(0.3, 0.3);
  tight.makeCoverageSafe(sensor, 5.0);
  GlobalSmoothingOptions wider = tight;
  wider.max_turning_radius = wider.vehicle.v_max / wider.vehicle.yaw_rate_max;
  const PolygonWithHoles area = lanesHull(20, 2.0);
  const std::vector<Point2> points = lanes(20, 2.0);
  const SmoothedPath slow = GlobalPathSmoother(area, tight).smooth(points);
  const SmoothedPath fast = GlobalPathSmoother(area, wider).smooth(points);
  testing::expectContinuousPath(fast, 100.0);
  int wide_arcs = 0;
  for (const PathPrimitive& p : fast.primitives) {
    if (p.kind() != PrimitiveKind::kArc) continue;
    EXPECT_GE(p.radius(), 0.3 - 1e-12);
    EXPECT_LE(p.radius(), 1.0 + 1e-12);
    EXPECT_GT(testing::sampledArcClearance(area, p, 0.005), 1e-9);
    if (p.radius() > 0.99) ++wide_arcs;
  }
  EXPECT_GE(wide_arcs, 30);
  EXPECT_LT(GlobalPathSmoother(area, wider).programme(points).plan().time,
            0.95 * GlobalPathSmoother(area, tight).programme(points).plan().time);
  EXPECT_LT(lostReachable(area, 5.0, points, fast, sensor), 0.05);
  EXPECT_GE(fast.statistics.turns_smoothed, slow.statistics.turns_smoothed);
}

TEST(GlobalSmoothingOptions, CoverageSafeTriesTheRadiusOfAnArcAtFullSpeed) {
  PlannerParameters parameters;
  parameters.turning_radius = 0.3;
  parameters.v_max = 0.6;
  parameters.yaw_rate_max = 0.5;
  EXPECT_DOUBLE_EQ(globalSmoothingOptionsOf(parameters).max_turning_radius, 1.2);
  parameters.max_turning_radius = 2.0;
  EXPECT_DOUBLE_EQ(globalSmoothingOptionsOf(parameters).max_turning_radius, 2.0);
  parameters.max_turning_radius = 0.0;
  parameters.turning_radius = 1.5;  // wider than the full-speed radius: nothing to add
  EXPECT_DOUBLE_EQ(globalSmoothingOptionsOf(parameters).max_turning_radius, 1.5);
  parameters.smoothing_strategy = "global";  // global keeps the candidates it was measured with
  parameters.turning_radius = 0.3;
  EXPECT_EQ(globalSmoothingOptionsOf(parameters).max_turning_radius, 0.0);
}

}  // namespace
}  // namespace kinematic_coverage::core
