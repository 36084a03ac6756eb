#include "polygon_coverage_ros_bridge/route/segment_cost.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "coverage_system/parameters/parameter_schema.h"
#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {
namespace {

PlannerParameters withCost(const std::string& cost_function) {
  PlannerParameters parameters;
  parameters.cost_function = cost_function;
  parameters.v_max = 0.5;
  parameters.a_max = 0.2;
  return parameters;
}

TEST(SegmentCost, DistanceIsLength) {
  const SegmentCost cost(segmentCostOf(withCost("distance")));
  EXPECT_DOUBLE_EQ(cost.of({0, 0}, {3, 4}), 5.0);
  EXPECT_DOUBLE_EQ(cost.ofLength(0.0), 0.0);
}

TEST(SegmentCost, TimeTrapezoidAboveCruiseLength) {
  const SegmentCost cost(segmentCostOf(withCost("time")));
  // v^2/a = 1.25 m; a 10 m segment cruises: 10/0.5 + 0.5/0.2.
  EXPECT_DOUBLE_EQ(cost.ofLength(10.0), 20.0 + 2.5);
}

TEST(SegmentCost, TimeTriangleBelowCruiseLength) {
  const SegmentCost cost(segmentCostOf(withCost("time")));
  EXPECT_DOUBLE_EQ(cost.ofLength(0.45), 2.0 * std::sqrt(0.45 / 0.2));
  EXPECT_DOUBLE_EQ(cost.ofLength(0.0), 0.0);
}

TEST(SegmentCost, TimeContinuousAtCruiseLength) {
  const SegmentCost cost(segmentCostOf(withCost("time")));
  const double cruise = 0.5 * 0.5 / 0.2;
  const double at = cost.ofLength(cruise);
  EXPECT_NEAR(at, 2.0 * 0.5 / 0.2, 1e-12);
  EXPECT_NEAR(cost.ofLength(std::nextafter(cruise, 0.0)), at, 1e-9);
  EXPECT_NEAR(cost.ofLength(cruise * (1.0 - 1e-9)), at, 1e-8);
  EXPECT_NEAR(cost.ofLength(cruise * (1.0 + 1e-9)), at, 1e-8);
}

TEST(SegmentCost, WaypointsCountSegments) {
  const SegmentCost cost(segmentCostOf(withCost("waypoints")));
  EXPECT_DOUBLE_EQ(cost.of({0, 0}, {0, 1e-3}), 1.0);
  EXPECT_DOUBLE_EQ(cost.of({0, 0}, {50, 0}), 1.0);
  EXPECT_DOUBLE_EQ(cost.of({1, 1}, {1, 1}), 0.0);
  EXPECT_DOUBLE_EQ(cost.pathCost({{0, 0}, {1, 0}, {1, 0}, {1, 1}}), 2.0);
}

TEST(SegmentCost, PathCostSumsSegmentsInEveryMode) {
  const std::vector<Point2> path = {{0, 0}, {3, 4}, {3, 4}, {3, 4.5}, {10, 4.5}};
  for (const char* mode : {"distance", "time", "waypoints"}) {
    const SegmentCost cost(segmentCostOf(withCost(mode)));
    double sum = 0.0;
    for (std::size_t i = 1; i < path.size(); ++i) sum += cost.of(path[i - 1], path[i]);
    EXPECT_DOUBLE_EQ(cost.pathCost(path), sum) << mode;
    EXPECT_DOUBLE_EQ(cost.pathCost({}), 0.0);
    EXPECT_DOUBLE_EQ(cost.pathCost({{1, 2}}), 0.0);
  }
  EXPECT_DOUBLE_EQ(pathLength(path), 5.0 + 0.5 + 7.0);
  EXPECT_DOUBLE_EQ(pathLength({}), 0.0);
}

TEST(SegmentCost, MonotoneAndSubadditiveOnRandomLengths) {
  // The router relies on it: a straight segment never costs more than a detour.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> length(0.0, 5.0);
  for (const char* mode : {"distance", "time", "waypoints"}) {
    const SegmentCost cost(segmentCostOf(withCost(mode)));
    for (int i = 0; i < 2000; ++i) {
      const double x = length(rng);
      const double y = length(rng);
      EXPECT_LE(cost.ofLength(x + y), cost.ofLength(x) + cost.ofLength(y) + 1e-12) << mode;
      EXPECT_LE(cost.ofLength(std::min(x, y)), cost.ofLength(std::max(x, y)) + 1e-12) << mode;
    }
  }
}

TEST(SegmentCost, RejectsBadParameters) {
  // The parameter set is checked where it is read; the mapping takes a checked one.
  EXPECT_THROW(checkParameters(withCost("energy")), InvalidInputError);
  PlannerParameters parameters = withCost("time");
  parameters.v_max = 0.0;
  EXPECT_THROW(segmentCostOf(parameters), InvalidInputError);
  // The stage itself checks the limits the time cost divides by; distance does not use them.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(SegmentCost(CostFunction::kTime, VehicleLimits{0.0, 0.2}), InvalidInputError);
  EXPECT_THROW(SegmentCost(CostFunction::kTime, VehicleLimits{0.5, nan}), InvalidInputError);
  EXPECT_NO_THROW(SegmentCost(CostFunction::kDistance, VehicleLimits{0.5, nan}));
  const SegmentCost cost(segmentCostOf(withCost("time")));
  EXPECT_THROW(cost.ofLength(-1.0), InvalidInputError);
  EXPECT_THROW(cost.of({0, 0}, {std::numeric_limits<double>::infinity(), 0}), InvalidInputError);
}

}  // namespace
}  // namespace kinematic_coverage::core
