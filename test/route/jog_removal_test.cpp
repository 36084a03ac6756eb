#include "polygon_coverage_ros_bridge/route/jog_removal.h"

#include <gtest/gtest.h>

#include <random>

#include "coverage_system/parameters/planner_parameters.h"
#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "test/route/route_test_maps.h"

namespace kinematic_coverage::core {
namespace {

/// A 20 m square with a square hole [8, 12]^2, distance cost.
PolygonWithHoles squareWithHole() {
  return {{{0, 0}, {20, 0}, {20, 20}, {0, 20}}, {{{8, 8}, {8, 12}, {12, 12}, {12, 8}}}};
}

PlannerParameters distanceCost() {
  PlannerParameters parameters;
  parameters.cost_function = "distance";
  return parameters;
}

/// Largest distance from any point of `original` to the polyline `result`.
double largestShift(const std::vector<Point2>& original, const std::vector<Point2>& result) {
  double largest = 0.0;
  for (const Point2& p : original) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i + 1 < result.size(); ++i) {
      nearest = std::min(nearest, distanceToSegment(p, result[i], result[i + 1]));
    }
    largest = std::max(largest, nearest);
  }
  return largest;
}

TEST(JogRemoval, RemovesAShortJogBetweenTwoLanes) {
  const PolygonWithHoles area = squareWithHole();
  const SegmentCost cost(segmentCostOf(distanceCost()));
  const VisibilityGraph graph(area, cost);
  // A lane to (6, 2), a 3 cm jog, a lane on to (18, 2.03).
  const std::vector<Point2> path = {{1, 2}, {6, 2}, {6.01, 2.03}, {18, 2.03}};
  const std::vector<Point2> result =
      JogRemoval(graph, 1.0, 0.5).apply(path, std::vector<bool>(path.size(), false));
  ASSERT_EQ(result.size(), 3u);
  EXPECT_EQ(result.front(), path.front());
  EXPECT_EQ(result.back(), path.back());
  EXPECT_LE(largestShift(path, result), 0.5);
}

// A pinned waypoint stays, as a kept one does, but is not reported as kept: the caller
// may still simplify it away where the path runs straight on.
TEST(JogRemoval, PinnedWaypointsStayWithoutBeingKept) {
  const PolygonWithHoles area = squareWithHole();
  const SegmentCost cost(segmentCostOf(distanceCost()));
  const VisibilityGraph graph(area, cost);
  const std::vector<Point2> path = {{1, 2}, {6, 2}, {6.01, 2.03}, {18, 2.03}};
  const std::vector<bool> keep(path.size(), false);
  std::vector<bool> pinned(path.size(), false);
  std::vector<bool> kept;
  const JogRemoval removal(graph, 1.0, 0.5);
  EXPECT_EQ(removal.apply(path, keep, &kept, &pinned).size(), 3u);
  pinned[1] = pinned[2] = true;
  EXPECT_EQ(removal.apply(path, keep, &kept, &pinned), path);
  EXPECT_EQ(kept, std::vector<bool>(path.size(), false));
  const std::vector<bool> too_few(2, true);
  EXPECT_THROW(removal.apply(path, keep, &kept, &too_few), InvalidInputError);
}

TEST(JogRemoval, KeepsJogsWhoseShortcutLeavesTheArea) {
  const PolygonWithHoles area = squareWithHole();
  const SegmentCost cost(segmentCostOf(distanceCost()));
  const VisibilityGraph graph(area, cost);
  // Around the hole's corner (12, 8): cutting it would cross the hole; the waypoint after
  // the corner is collinear and goes.
  const std::vector<Point2> path = {{2, 7.9}, {12.1, 7.9}, {12.1, 8.3}, {12.1, 14}};
  const std::vector<Point2> result =
      JogRemoval(graph, 1.0, 5.0).apply(path, std::vector<bool>(path.size(), false));
  for (std::size_t i = 0; i + 1 < result.size(); ++i) {
    EXPECT_TRUE(graph.visible(result[i], result[i + 1]));
  }
  ASSERT_EQ(result.size(), 3u);
  EXPECT_EQ(result[1], path[1]);
}

TEST(JogRemoval, KeepsLongLegsLargeDeviationsAndProtectedWaypoints) {
  const PolygonWithHoles area = squareWithHole();
  const SegmentCost cost(segmentCostOf(distanceCost()));
  const VisibilityGraph graph(area, cost);
  const std::vector<Point2> path = {{1, 2}, {6, 2}, {6.0, 2.3}, {18, 2.3}};
  // Legs of at least 2 m: nothing is short.
  EXPECT_EQ(JogRemoval(graph, 0.2, 1.0).apply(path, std::vector<bool>(4, false)).size(), 4u);
  // Deviation 0.29 m above the bound of 0.1 m.
  EXPECT_EQ(JogRemoval(graph, 1.0, 0.1).apply(path, std::vector<bool>(4, false)).size(), 4u);
  // Both jog ends protected.
  std::vector<bool> kept;
  const auto result = JogRemoval(graph, 1.0, 1.0).apply(path, {false, true, true, false}, &kept);
  EXPECT_EQ(result.size(), 4u);
  EXPECT_EQ(kept, (std::vector<bool>{false, true, true, false}));
}

TEST(JogRemoval, DropsDuplicatesAndRejectsBadArguments) {
  const PolygonWithHoles area = squareWithHole();
  const SegmentCost cost(segmentCostOf(distanceCost()));
  const VisibilityGraph graph(area, cost);
  const std::vector<Point2> path = {{1, 2}, {6, 2}, {6, 2}, {6, 6}};
  EXPECT_EQ(JogRemoval(graph, 1.0, 0.0).apply(path, std::vector<bool>(4, false)).size(), 3u);
  EXPECT_THROW(JogRemoval(graph, -1.0, 0.1), InvalidInputError);
  EXPECT_THROW(JogRemoval(graph, 1.0, std::nan("")), InvalidInputError);
  EXPECT_THROW(JogRemoval(graph, 1.0, 0.1).apply(path, {true}), InvalidInputError);
}

/// Random zig-zag paths with jittered waypoints on maps with convex holes: every leg of
/// the result stays inside, the ends and protected waypoints stay, and every original
/// waypoint lies within the deviation bound of the result.
TEST(JogRemoval, RandomPathsStayInsideAndNearTheOriginal) {
  std::mt19937 rng(4242);
  const SegmentCost cost(segmentCostOf(distanceCost()));
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int removed = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const PolygonWithHoles map = testing::convexHolesMap(rng, 40.0, 4, 3, 7, 2.0);
    const VisibilityGraph graph(map, cost);
    std::vector<Point2> anchors;
    while (anchors.size() < 12) {
      const Point2 p(1 + 38 * unit(rng), 1 + 38 * unit(rng));
      if (contains(map, p, 0.0) && distanceToBoundary(p, map) > 0.2) anchors.push_back(p);
    }
    // Each leg of the route between anchors, with short jogs beside some of its waypoints.
    std::vector<Point2> path;
    for (std::size_t i = 0; i + 1 < anchors.size(); ++i) {
      const std::vector<Point2> leg = graph.shortestPath(anchors[i], anchors[i + 1]);
      for (std::size_t j = i == 0 ? 0 : 1; j < leg.size(); ++j) {
        path.push_back(leg[j]);
        const Point2 jog = leg[j] + Point2(0.1 * (unit(rng) - 0.5), 0.1 * (unit(rng) - 0.5));
        if (j + 1 < leg.size() && contains(map, jog, 0.0) && graph.visible(leg[j], jog) &&
            graph.visible(jog, leg[j + 1])) {
          path.push_back(jog);
        }
      }
    }
    std::vector<bool> keep(path.size(), false);
    keep.front() = keep.back() = true;
    keep[path.size() / 2] = true;
    std::vector<bool> kept;
    const double bound = 0.3;
    const std::vector<Point2> result = JogRemoval(graph, 0.5, bound).apply(path, keep, &kept);
    removed += static_cast<int>(path.size() - result.size());
    ASSERT_GE(result.size(), 2u);
    EXPECT_EQ(result.front(), path.front());
    EXPECT_EQ(result.back(), path.back());
    EXPECT_NE(std::find(result.begin(), result.end(), path[path.size() / 2]), result.end());
    EXPECT_EQ(kept.size(), result.size());
    for (std::size_t i = 0; i + 1 < result.size(); ++i) {
      EXPECT_TRUE(graph.visible(result[i], result[i + 1])) << "trial " << trial << " leg " << i;
    }
    EXPECT_LE(largestShift(path, result), bound + 1e-9) << "trial " << trial;
  }
  EXPECT_GT(removed, 0);
}

}  // namespace
}  // namespace kinematic_coverage::core
