// The smoothed path's properties for every smoothing strategy: Algorithm 1
// (PathSmoother) and the global programme (GlobalPathSmoother) at one radius, with a
// variable radius, coverage-preserving and coverage-safe. On seeded random paths among random
// holes: continuity (positions and headings), statistics that match the primitives, arcs clear of
// the hull and holes, curvature at most 1 / min_turning_radius.
#include <gtest/gtest.h>

#include <functional>
#include <ostream>
#include <random>
#include <string>

#include "test/smoothing/smoothing_oracle.h"
#include "trajectory_generation_tools/smoothing/global_path_smoother.h"
#include "trajectory_generation_tools/smoothing/path_smoother.h"

namespace kinematic_coverage::core {
namespace {

/// One strategy: how it smooths a path with preferred radius r, and its least radius.
struct Strategy {
  std::string name;
  std::function<SmoothedPath(const PolygonWithHoles&, double, const std::vector<Point2>&)> smooth;
  double min_radius_fraction = 1.0;  ///< min_turning_radius / turning_radius
  int trials = 300;
  /// Least fraction of the turns smoothed over all trials: coverage preservation keeps
  /// most of these random, mostly wide turns sharp.
  double min_smoothed_fraction = 1.0 / 3.0;
};

/// gtest prints a strategy by its name.
void PrintTo(const Strategy& strategy, std::ostream* os) { *os << strategy.name; }

GlobalSmoothingOptions globalOptions(double radius, double min_radius_fraction) {
  GlobalSmoothingOptions options;
  options.vehicle.turning_radius = radius;
  options.min_turning_radius = min_radius_fraction * radius;
  return options;
}

std::vector<Strategy> strategies() {
  return {
      {"local",
       [](const PolygonWithHoles& area, double r, const std::vector<Point2>& points) {
         return PathSmoother(area, r).smooth(points);
       }},
      {"global",
       [](const PolygonWithHoles& area, double r, const std::vector<Point2>& points) {
         return GlobalPathSmoother(area, globalOptions(r, 1.0)).smooth(points);
       }},
      {"global_variable_radius",
       [](const PolygonWithHoles& area, double r, const std::vector<Point2>& points) {
         return GlobalPathSmoother(area, globalOptions(r, 0.4)).smooth(points);
       },
       0.4},
      {"global_coverage_preserving",
       [](const PolygonWithHoles& area, double r, const std::vector<Point2>& points) {
         GlobalSmoothingOptions options = globalOptions(r, 1.0);
         options.preserved_sensor = FrustumSensor(4.0, 3.0, 0.0);
         return GlobalPathSmoother(area, options).smooth(points);
       },
       1.0, 60, 0.01},
      {"coverage_safe",
       [](const PolygonWithHoles& area, double r, const std::vector<Point2>& points) {
         GlobalSmoothingOptions options = globalOptions(r, 1.0);
         options.makeCoverageSafe(FrustumSensor(4.0, 3.0, 0.0), 0.0);
         return GlobalPathSmoother(area, options).smooth(points);
       },
       1.0, 60, 0.01},
  };
}

class SmoothingStrategyProperties : public ::testing::TestWithParam<Strategy> {};

/// A square of 120 m with up to six disjoint rectangular holes of 1 to 5 m.
PolygonWithHoles randomArea(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  PolygonWithHoles area;
  area.hull = testing::squareHull({0, 0}, 60);
  for (int k = 0; k < 6; ++k) {
    const Point2 low(80 * unit(rng) - 40, 80 * unit(rng) - 40);
    area.holes.push_back(
        testing::rectangleHole(low, low + Point2(1 + 4 * unit(rng), 1 + 4 * unit(rng))));
    for (std::size_t j = 0; j + 1 < area.holes.size(); ++j) {
      const Ring& a = area.holes[j];
      const Ring& b = area.holes.back();
      if (a[0].x() <= b[2].x() && b[0].x() <= a[2].x() && a[0].y() <= b[2].y() &&
          b[0].y() <= a[2].y()) {
        area.holes.pop_back();
        break;
      }
    }
  }
  return area;
}

/// 30 random waypoints with duplicates, straight continuations and, for the global
/// strategy's reverse curves, short jogs.
std::vector<Point2> randomPath(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Point2> points;
  for (int k = 0; k < 30; ++k) {
    const double kind = unit(rng);
    if (!points.empty() && kind < 0.1) {
      points.push_back(points.back());
    } else if (points.size() >= 2 && kind < 0.2) {
      points.push_back(points.back() + (points.back() - points[points.size() - 2]));
    } else if (points.size() >= 2 && kind < 0.35) {
      // A jog: a short step across, then on in the previous direction.
      const Point2 along = (points.back() - points[points.size() - 2]).normalized();
      const Point2 across(-along.y(), along.x());
      const Point2 step = points.back() + (0.5 + 3 * unit(rng)) * across;
      points.push_back(step);
      points.push_back(step + (5 + 20 * unit(rng)) * along);
    } else {
      points.push_back({100 * unit(rng) - 50, 100 * unit(rng) - 50});
    }
  }
  return points;
}

TEST_P(SmoothingStrategyProperties, RandomPathsAreContinuousFreeAndWithinCurvature) {
  const Strategy& strategy = GetParam();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int smoothed = 0;
  int turns = 0;
  for (int trial = 0; trial < strategy.trials; ++trial) {
    const PolygonWithHoles area = randomArea(rng);
    const std::vector<Point2> points = randomPath(rng);
    const double r = 0.3 + 3 * unit(rng);
    const SmoothedPath path = strategy.smooth(area, r, points);
    SCOPED_TRACE(strategy.name + " trial " + std::to_string(trial));
    testing::expectContinuousPath(path, 150.0);
    ASSERT_FALSE(path.primitives.empty());
    EXPECT_TRUE(path.primitives.front().start().isApprox(points.front(), 1e-9));
    smoothed += path.statistics.turns_smoothed;
    turns += path.statistics.turns_total;
    for (const PathPrimitive& p : path.primitives) {
      if (p.kind() != PrimitiveKind::kArc) continue;
      ASSERT_NE(testing::sampledArcClearance(area, p, 0.01 * r), -1.0);
      EXPECT_LE(p.curvature(), (1 + 1e-12) / (strategy.min_radius_fraction * r));
    }
    if (::testing::Test::HasFailure()) return;
  }
  EXPECT_GT(smoothed, strategy.min_smoothed_fraction * turns) << smoothed << " of " << turns;
}

INSTANTIATE_TEST_SUITE_P(AllStrategies, SmoothingStrategyProperties,
                         ::testing::ValuesIn(strategies()),
                         [](const ::testing::TestParamInfo<Strategy>& info) {
                           return info.param.name;
                         });

}  // namespace
}  // namespace kinematic_coverage::core
