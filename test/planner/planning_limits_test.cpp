#include "coverage_system/planner/planning_limits.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/gtsp/gtsp_instance.h"

namespace kinematic_coverage::core {
namespace {

/// One decomposition of `cells` 10 x 4 m rectangles, each with `directions` lane directions
/// (best first: 0, then 0.1, 0.2, ... radians).
std::vector<Decomposition> rectangles(std::size_t cells, std::size_t directions) {
  Decomposition decomposition;
  for (std::size_t i = 0; i < cells; ++i) {
    Cell cell;
    const double x = 20.0 * static_cast<double>(i);
    cell.polygon = {{x, 0}, {x + 10, 0}, {x + 10, 4}, {x, 4}};
    for (std::size_t d = 0; d < directions; ++d) cell.sweep_directions.push_back(0.1 * d);
    decomposition.cells.push_back(cell);
  }
  return {decomposition};
}

TEST(PlanningLimits, GtspNodesAreFourPerDirectionPlusStartAndGoal) {
  EXPECT_EQ(gtspNodeCount(rectangles(3, 2)), 3u * 2u * 4u + 2u);
  EXPECT_EQ(gtspNodeCount({}), 2u);
}

TEST(PlanningLimits, DirectionsWithinTheGtspLimitAreKept) {
  std::vector<Decomposition> decompositions = rectangles(10, 4);
  EXPECT_EQ(fitDirectionsToGtspLimit(decompositions), 0u);
  EXPECT_EQ(gtspNodeCount(decompositions), 10u * 4u * 4u + 2u);
}

TEST(PlanningLimits, OverTheGtspLimitEveryCellKeepsItsBestDirectionsFirst) {
  // 1 000 cells with 4 directions each: 16 002 nodes, over kMaxGtspNodes.
  std::vector<Decomposition> decompositions = rectangles(1000, 4);
  const std::size_t before = gtspNodeCount(decompositions);
  ASSERT_GT(before, static_cast<std::size_t>(kMaxGtspNodes));
  const std::size_t dropped = fitDirectionsToGtspLimit(decompositions);
  const std::size_t after = gtspNodeCount(decompositions);
  EXPECT_LE(after, static_cast<std::size_t>(kMaxGtspNodes));
  // No room for one more direction anywhere, and the nodes dropped are the directions'.
  EXPECT_GT(after + 4, static_cast<std::size_t>(kMaxGtspNodes));
  EXPECT_EQ(before - after, 4 * dropped);
  std::size_t previous = 4;
  for (const Cell& cell : decompositions.front().cells) {
    // Every cell keeps a prefix of its directions (best first), earlier cells no fewer.
    ASSERT_GE(cell.sweep_directions.size(), 1u);
    EXPECT_LE(cell.sweep_directions.size(), previous);
    previous = cell.sweep_directions.size();
    for (std::size_t d = 0; d < cell.sweep_directions.size(); ++d) {
      EXPECT_DOUBLE_EQ(cell.sweep_directions[d], 0.1 * d);
    }
  }
}

TEST(PlanningLimits, MinimumLaneCountIsTheWidthOverTheSweepDistance) {
  // 10 x 4 m rectangles: 4 m across direction 0 (lanes along x), at least one lane.
  EXPECT_DOUBLE_EQ(minimumLaneCount(rectangles(3, 1), 0.5), 3 * 8.0);
  EXPECT_DOUBLE_EQ(minimumLaneCount(rectangles(3, 1), 100.0), 3 * 1.0);
}

TEST(PlanningLimits, EveryCellKeepsItsBestDirectionBeyondTheGtspLimit) {
  // 2 000 cells: 8 002 nodes with one direction each, over kMaxGtspNodes; none is refused.
  std::vector<Decomposition> decompositions = rectangles(2000, 3);
  fitDirectionsToGtspLimit(decompositions);
  for (const Cell& cell : decompositions.front().cells) EXPECT_EQ(cell.sweep_directions.size(), 1u);
  EXPECT_EQ(gtspNodeCount(decompositions), 2000u * 4u + 2u);
}

TEST(PlanningLimits, RouteCornersAreTheCornersWhereTheAreaTurnsBackOnItself) {
  // An L-shaped hull (one reflex corner) with a square hole (four), either orientation.
  Ring hull = {{0, 0}, {10, 0}, {10, 4}, {4, 4}, {4, 10}, {0, 10}};
  Ring hole = {{1, 1}, {1, 2}, {2, 2}, {2, 1}};
  EXPECT_EQ(routeCorners({hull, {hole}}), 5u);
  std::reverse(hull.begin(), hull.end());
  std::reverse(hole.begin(), hole.end());
  EXPECT_EQ(routeCorners({hull, {hole}}), 5u);
}

TEST(PlanningLimits, TheMemoryEstimateGrowsWithTheSquaresAndRefusesWithWhatToChange) {
  const PlanSize small{10, 42, 30};
  const PlanSize large{2000, 8002, 9000};
  const double mib = 1024.0 * 1024.0;
  EXPECT_GE(planMemoryEstimateBytes(small), kMemoryBaselineBytes);
  EXPECT_LT(planMemoryEstimateBytes(small), kMemoryBaselineBytes + mib);
  // The quadratic terms: 8.5 V^2 + 8 n V + 24 n^2 + 24 m^2 bytes.
  EXPECT_NEAR(planMemoryEstimateBytes(large) - kMemoryBaselineBytes,
              8.5 * 9000.0 * 9000.0 + 8.0 * 8002.0 * 9000.0 + 24.0 * 8002.0 * 8002.0 +
                  24.0 * 2000.0 * 2000.0,
              1.0);
  // A graph searched on demand and lazy transitions: linear in V, one n^2 matrix.
  PlanSize chart = large;
  chart.routes_on_demand = true;
  chart.lazy_transitions = true;
  EXPECT_NEAR(planMemoryEstimateBytes(chart) - kMemoryBaselineBytes,
              kOnDemandBytesPerCorner * 9000.0 + 8.0 * 8002.0 * 8002.0 + 24.0 * 2000.0 * 2000.0,
              1.0);
  EXPECT_NO_THROW(checkMemoryEstimate(large, 4096.0, DecompositionType::kBoustrophedon));
  try {
    checkMemoryEstimate(large, 1000.0, DecompositionType::kTrapezoidal);
    ADD_FAILURE() << "accepted the large plan within 1000 MB";
  } catch (const SizeLimitError& error) {
    const std::string message = error.what();
    const long estimate_mb = std::lround(planMemoryEstimateBytes(large) / mib);
    EXPECT_NE(message.find("would need about " + std::to_string(estimate_mb) +
                           " MB, more than max_memory_mb 1000 MB (2000 cells with 8002 "
                           "generalized TSP nodes"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("9000 corners"), std::string::npos) << message;
    EXPECT_NE(message.find("simplify the polygon"), std::string::npos) << message;
    EXPECT_NE(message.find("fewer cells than the trapezoidal"), std::string::npos) << message;
  }
  EXPECT_GT(machineMaxMemoryMb(), 0.0);
}

TEST(PlanningLimits, LaneLimitRefusesWithWhatToChange) {
  PlannerParameters parameters;
  // 4 m across at a sweep distance of 0.01 m: 400 lanes per cell.
  parameters.sensor_model = "line";
  parameters.lateral_footprint = 0.02;
  parameters.lateral_overlap = 0.5;
  const std::size_t fitting = kMaxSweeps / 400;
  EXPECT_NO_THROW(checkLaneLimit(rectangles(fitting, 1), sensorOptionsOf(parameters)));
  try {
    checkLaneLimit(rectangles(2 * fitting, 1), sensorOptionsOf(parameters));
    ADD_FAILURE() << "accepted " << 2 * fitting * 400 << " lanes";
  } catch (const InvalidInputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("at least " + std::to_string(2 * fitting * 400) + " sweep lanes, " +
                           std::to_string(fitting * 400) + " more than the limit of " +
                           std::to_string(kMaxSweeps)),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("grow about 2 times"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
