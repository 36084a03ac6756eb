// Coverage on the raster that coverage_tool reports on (reportingResolution) against the
// seen areas of motions known in closed form, to 0.1 % of the free area (a straight sweep
// over a rectangle, a full circle turn, an in-place rotation).
// The trajectories are sampled as TrajectoryGenerator samples them (0.5 m segments, 0.1 m
// arcs, 0.2 rad rotations) unless a case needs the continuous motion.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "trajectory_generation_tools/coverage/coverage_evaluator.h"

namespace kinematic_coverage::core {
namespace {

/// The free area: a 40 m square; the offset free area 1 m inside it.
const PolygonWithHoles kFreeArea{{{0, 0}, {40, 0}, {40, 40}, {0, 40}}, {}};
const PolygonWithHoles kOffsetFreeArea{{{1, 1}, {39, 1}, {39, 39}, {1, 39}}, {}};
constexpr double kFreeAreaM2 = 1600.0;

/// Footprints W x L of the thesis's sensors at d = 3 m: lateral_fov 2.27 rad (the lake
/// missions) and 1.2 rad (the acute-corner mission), onward_fov 0.52 rad.
const FrustumSensor kWideSensor(6.0 * std::tan(2.27 / 2.0), 6.0 * std::tan(0.26), 0.0);
const FrustumSensor kNarrowSensor(6.0 * std::tan(0.6), 6.0 * std::tan(0.26), 0.0);

/// The reported coverage's accuracy: 0.1 % of the free area, in square metres.
constexpr double kTolerance = 1e-3 * kFreeAreaM2;

/// Area of the free area's cells that `poses` see, on the reporting raster.
double seenFreeArea(const FrustumSensor& sensor, const std::vector<Pose2>& poses) {
  const CoverageEvaluator evaluator(kFreeArea, {kOffsetFreeArea}, sensor, reportingResolution());
  EXPECT_LE(evaluator.raster().cellSize(), kReportingCellSize);
  const CoverageReport report = evaluator.report(evaluator.seeTrajectory(poses));
  EXPECT_NEAR(report.coverage_loss_percent, 100.0 - report.coverage_percent, 1e-9);
  return report.coverage_percent / 100.0 * kFreeAreaM2;
}

/// Poses from `from`, `length` metres along `heading`, at most `spacing` apart.
std::vector<Pose2> straightRun(const Point2& from, double heading, double length,
                               double spacing = 0.5) {
  const Point2 direction(std::cos(heading), std::sin(heading));
  const int steps = static_cast<int>(std::ceil(length / spacing));
  std::vector<Pose2> poses;
  for (int k = 0; k <= steps; ++k) {
    const Point2 p = from + (length * k / steps) * direction;
    poses.push_back({p.x(), p.y(), heading});
  }
  return poses;
}

/// Poses once around the circle of `radius` about `centre`, counter-clockwise, heading
/// along the tangent, at most `spacing` apart along the arc.
std::vector<Pose2> circleTurn(const Point2& centre, double radius, double spacing = 0.1) {
  const int steps = static_cast<int>(std::ceil(2.0 * M_PI * radius / spacing));
  std::vector<Pose2> poses;
  for (int k = 0; k <= steps; ++k) {
    const double angle = 2.0 * M_PI * k / steps;
    poses.push_back({centre.x() + radius * std::cos(angle), centre.y() + radius * std::sin(angle),
                     angle + 0.5 * M_PI});
  }
  return poses;
}

/// Poses of one full turn in place at `centre`, `steps` equal steps.
std::vector<Pose2> turnInPlace(const Point2& centre, int steps) {
  std::vector<Pose2> poses;
  for (int k = 0; k <= steps; ++k) {
    poses.push_back({centre.x(), centre.y(), 0.3 + 2.0 * M_PI * k / steps});
  }
  return poses;
}

TEST(AnalyticCoverage, ReportingRasterHasCellsOfAtMostFiveCentimetresOnSmallMaps) {
  EXPECT_LE(kReportingCellSize, 0.05);
  // On a 400 m square the cells that meet the worst-case bound of 0.1 % are coarser,
  // 2 * 1e-3 * area / perimeter = 0.2 m, and used; the 4 000 000-cell budget (2002 x
  // 2002 would be needed with the margin) coarsens them by 1 % more.
  const double side = 400.0;
  const PolygonWithHoles large{{{0, 0}, {side, 0}, {side, side}, {0, side}}, {}};
  const CoverageRaster raster = CoverageRaster::covering(large, reportingResolution());
  const double bound_cell_size = 2.0 * 1e-3 * side * side / (4.0 * side);
  EXPECT_GE(raster.cellSize(), bound_cell_size);
  EXPECT_LE(raster.cellSize(), 1.011 * bound_cell_size);
}

TEST(AnalyticCoverage, StraightSweepSeesTheHullOfItsEndFootprints) {
  // Two footprints W x L aligned along the run: their hull is W x (run + L).
  for (const FrustumSensor& sensor : {kWideSensor, kNarrowSensor}) {
    for (const double heading : {0.0, 0.3, 1.1, 0.5 * M_PI, -2.5}) {
      const Point2 middle(20.013, 19.371);
      const double run = 20.0;
      const Point2 from = middle - 0.5 * run * Point2(std::cos(heading), std::sin(heading));
      const double expected = sensor.width() * (run + sensor.length());
      EXPECT_NEAR(seenFreeArea(sensor, straightRun(from, heading, run)), expected, kTolerance)
          << "W " << sensor.width() << " heading " << heading;
    }
  }
}

TEST(AnalyticCoverage, SweepAcrossTheRectangleSeesAStripOfIt) {
  // From outside the free area across all of it: the part seen is W x 40 m.
  for (const FrustumSensor& sensor : {kWideSensor, kNarrowSensor}) {
    const std::vector<Pose2> poses = straightRun({-5.0, 17.29}, 0.0, 50.0);
    EXPECT_NEAR(seenFreeArea(sensor, poses), sensor.width() * 40.0, kTolerance)
        << "W " << sensor.width();
  }
}

TEST(AnalyticCoverage, FullCircleTurnSeesAnAnnulus) {
  // A footprint W across the heading and L along it, centred on a circle of radius R: its
  // points lie between R - W/2 (the middle of its inner edge) and sqrt((R + W/2)^2 +
  // (L/2)^2) (its outer corners) from the centre, and a full turn sweeps every radius in
  // between in every direction. When R <= W/2 the footprint covers the centre: a disk.
  const Point2 centre(20.0, 20.0);
  struct Case {
    FrustumSensor sensor;
    double radius;
  };
  for (const Case& c : {Case{kNarrowSensor, 3.0}, Case{kNarrowSensor, 8.0}, Case{kWideSensor, 8.0},
                        Case{kWideSensor, 1.0}}) {
    const double half_width = 0.5 * c.sensor.width();
    const double half_length = 0.5 * c.sensor.length();
    const double outer_squared =
        (c.radius + half_width) * (c.radius + half_width) + half_length * half_length;
    const double inner = std::max(0.0, c.radius - half_width);
    const double expected = M_PI * (outer_squared - inner * inner);
    EXPECT_NEAR(seenFreeArea(c.sensor, circleTurn(centre, c.radius)), expected, kTolerance)
        << "W " << c.sensor.width() << " R " << c.radius;
  }
}

TEST(AnalyticCoverage, FullTurnInPlaceSeesTheDiskOfHalfTheDiagonal) {
  // Turning continuously (finely sampled), the footprint's corners draw the circle of
  // radius sqrt((W/2)^2 + (L/2)^2).
  for (const FrustumSensor& sensor : {kWideSensor, kNarrowSensor}) {
    const double radius_squared =
        0.25 * (sensor.width() * sensor.width() + sensor.length() * sensor.length());
    EXPECT_NEAR(seenFreeArea(sensor, turnInPlace({20.0, 20.0}, 4000)), M_PI * radius_squared,
                kTolerance)
        << "W " << sensor.width();
  }
}

/// Area of the union of `sensor`'s footprints at `yaws` about one centre: each footprint
/// is convex around the centre, so the union is star-shaped with the largest of their
/// radial functions, r(phi) = min((L/2) / |cos phi|, (W/2) / |sin phi|) at angle phi from
/// the heading; area = 1/2 * integral of r^2 (midpoint rule).
double unionOfTurnedFootprints(const FrustumSensor& sensor, const std::vector<double>& yaws) {
  const int samples = 1'000'000;
  const double step = 2.0 * M_PI / samples;
  double area = 0.0;
  for (int i = 0; i < samples; ++i) {
    const double angle = (i + 0.5) * step;
    double radius = 0.0;
    for (const double yaw : yaws) {
      const double along = std::abs(std::cos(angle - yaw));
      const double across = std::abs(std::sin(angle - yaw));
      radius =
          std::max(radius, std::min(0.5 * sensor.length() / along, 0.5 * sensor.width() / across));
    }
    area += 0.5 * radius * radius * step;
  }
  return area;
}

TEST(AnalyticCoverage, SampledTurnInPlaceSeesTheUnionOfItsFootprints) {
  // A trajectory's rotation poses share a position: the area seen is the union of their
  // footprints, which misses slivers of the disk between them.
  for (const FrustumSensor& sensor : {kWideSensor, kNarrowSensor}) {
    const std::vector<Pose2> poses = turnInPlace({20.0, 20.0}, 32);  // 0.196 rad apart
    std::vector<double> yaws;
    for (const Pose2& pose : poses) yaws.push_back(pose.yaw);
    const double expected = unionOfTurnedFootprints(sensor, yaws);
    EXPECT_NEAR(seenFreeArea(sensor, poses), expected, kTolerance) << "W " << sensor.width();
    const double disk =
        0.25 * M_PI * (sensor.width() * sensor.width() + sensor.length() * sensor.length());
    EXPECT_LT(expected, disk);
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
