#include "polygon_coverage_ros_bridge/route/visibility_graph.h"

#include <gtest/gtest.h>

#include <cmath>
#include <ctime>
#include <iomanip>
#include <iostream>
#include <memory>
#include <numeric>
#include <random>
#include <utility>

#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"
#include "test/route/route_test_maps.h"
#include "test/support/random_polygons.h"

namespace kinematic_coverage::core {
namespace {

SegmentCost costOf(const std::string& cost_function) {
  PlannerParameters parameters;
  parameters.cost_function = cost_function;
  return SegmentCost(segmentCostOf(parameters));
}

PolygonWithHoles squareWithHole() {
  return {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{4, 4}, {4, 6}, {6, 6}, {6, 4}}}};
}

void expectPathInside(const PolygonWithHoles& area, const std::vector<Point2>& path) {
  for (std::size_t i = 1; i < path.size(); ++i) {
    EXPECT_TRUE(segmentInside(area, path[i - 1], path[i], 1e-6))
        << "leg " << i << " from " << path[i - 1].transpose() << " to " << path[i].transpose();
  }
}

TEST(VisibilityGraph, AroundOneSquareHoleIsAnalytic) {
  const PolygonWithHoles area = squareWithHole();
  const VisibilityGraph graph(area, costOf("distance"));
  EXPECT_EQ(graph.nodeCount(), 4u);
  const std::vector<Point2> path = graph.shortestPath({2, 5}, {8, 5});
  ASSERT_EQ(path.size(), 4u);
  EXPECT_EQ(path.front(), Point2(2, 5));
  EXPECT_EQ(path.back(), Point2(8, 5));
  EXPECT_NEAR(std::abs(path[1].y() - 5.0), 1.0, 1e-12);
  EXPECT_NEAR(pathLength(path), 2.0 + 2.0 * std::sqrt(5.0), 1e-12);
  EXPECT_NEAR(graph.cost({2, 5}, {8, 5}), 2.0 + 2.0 * std::sqrt(5.0), 1e-12);
  expectPathInside(area, path);
  // Visible ends go straight.
  EXPECT_EQ(graph.shortestPath({1, 1}, {9, 2}).size(), 2u);
}

TEST(VisibilityGraph, TimeCostStopsAtEveryBend) {
  const VisibilityGraph graph(squareWithHole(), costOf("time"));
  const SegmentCost time = costOf("time");
  const std::vector<Point2> path = graph.shortestPath({2, 5}, {8, 5});
  EXPECT_NEAR(graph.cost({2, 5}, {8, 5}), time.pathCost(path), 1e-9);
  EXPECT_NEAR(graph.cost({2, 5}, {8, 5}), 2.0 * time.ofLength(std::sqrt(5.0)) + time.ofLength(2.0),
              1e-9);
}

TEST(VisibilityGraph, InAUShapedPolygon) {
  const PolygonWithHoles area{
      {{0, 0}, {10, 0}, {10, 10}, {7, 10}, {7, 3}, {3, 3}, {3, 10}, {0, 10}}, {}};
  const VisibilityGraph graph(area, costOf("distance"));
  EXPECT_EQ(graph.nodeCount(), 2u);
  const std::vector<Point2> path = graph.shortestPath({1.5, 9}, {8.5, 9});
  const std::vector<Point2> expected = {{1.5, 9}, {3, 3}, {7, 3}, {8.5, 9}};
  ASSERT_EQ(path.size(), expected.size());
  for (std::size_t i = 0; i < path.size(); ++i)
    EXPECT_NEAR((path[i] - expected[i]).norm(), 0, 1e-12);
  EXPECT_NEAR(graph.cost({1.5, 9}, {8.5, 9}), 4.0 + 2.0 * std::hypot(1.5, 6.0), 1e-12);
  // From the reflex vertices themselves, and along the inner walls.
  EXPECT_NEAR(graph.cost({3, 3}, {8.5, 9}), 4.0 + std::hypot(1.5, 6.0), 1e-12);
  EXPECT_NEAR(graph.cost({3, 10}, {7, 10}), 7.0 + 4.0 + 7.0, 1e-12);
  expectPathInside(area, graph.shortestPath({3, 10}, {7, 10}));
}

TEST(VisibilityGraph, ThroughAPinchBetweenTwoHoles) {
  const PolygonWithHoles area{{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                              {{{2, 2}, {2, 5}, {5, 5}, {5, 2}}, {{5, 5}, {5, 8}, {8, 8}, {8, 5}}}};
  const VisibilityGraph graph(area, costOf("distance"));
  EXPECT_EQ(graph.shortestPath({2, 8}, {8, 2}).size(), 2u);
  // From below-left of the pinch to up-left: around the left hole or through the pinch.
  const double through_pinch = std::hypot(4.0, 1.0) + std::hypot(1.0, 3.0);
  EXPECT_NEAR(graph.cost({1, 4}, {4, 8}), std::hypot(3.0, 4.0), 1e-12);  // straight
  EXPECT_NEAR(graph.cost({9, 4}, {6, 2}), std::hypot(3.0, 2.0), 1e-12);
  EXPECT_NEAR(graph.cost({1, 6}, {6, 2}), through_pinch, 1e-12);
  expectPathInside(area, graph.shortestPath({1, 6}, {6, 2}));
}

TEST(VisibilityGraph, ThroughAPinchOfTheHull) {
  const PolygonWithHoles area{{{0, 0}, {5, 0}, {5, 5}, {10, 5}, {10, 10}, {5, 10}, {5, 5}, {0, 5}},
                              {}};
  const VisibilityGraph graph(area, costOf("distance"));
  const std::vector<Point2> path = graph.shortestPath({1, 4}, {6, 9});
  ASSERT_EQ(path.size(), 3u);
  EXPECT_EQ(path[1], Point2(5, 5));
  EXPECT_NEAR(pathLength(path), 2.0 * std::sqrt(17.0), 1e-12);
  EXPECT_EQ(graph.shortestPath({1, 1}, {9, 9}).size(), 2u);
}

TEST(VisibilityGraph, ThroughAHoleTouchingTheHull) {
  const PolygonWithHoles area{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{5, 0}, {3, 4}, {7, 4}}}};
  const VisibilityGraph graph(area, costOf("distance"));
  const std::vector<Point2> path = graph.shortestPath({1, 1}, {9, 1});
  ASSERT_EQ(path.size(), 3u);
  EXPECT_EQ(path[1], Point2(5, 0));
  EXPECT_NEAR(pathLength(path), 2.0 * std::sqrt(17.0), 1e-12);
  // High enough, going over the hole is shorter.
  EXPECT_NEAR(graph.cost({1, 4}, {9, 4}), 8.0, 1e-12);
}

TEST(VisibilityGraph, BoundaryPointsAndNodesAreQueryPoints) {
  const PolygonWithHoles area = squareWithHole();
  const VisibilityGraph graph(area, costOf("distance"));
  EXPECT_NEAR(graph.cost({4, 5}, {6, 5}), 4.0, 1e-12);
  EXPECT_NEAR(graph.cost({4, 4}, {6, 6}), 4.0, 1e-12);
  EXPECT_NEAR(graph.cost({4, 4}, {6, 4}), 2.0, 1e-12);
  EXPECT_NEAR(graph.cost({0, 5}, {10, 5}), 2.0 * std::hypot(4.0, 1.0) + 2.0, 1e-12);
  expectPathInside(area, graph.shortestPath({4, 5}, {6, 5}));
  expectPathInside(area, graph.shortestPath({4, 4}, {6, 6}));
  // A point a rounding error outside the boundary counts as on it.
  EXPECT_NEAR(graph.cost({4.0 - 1e-14, 5}, {6.0 + 1e-14, 5}), 4.0, 1e-9);
}

TEST(VisibilityGraph, BoundaryPointJustPastAConvexCornerRoutesAlongTheWall) {
  // A lane end on the corridor's lower wall just past its bend: the cheapest route runs
  // back along the wall to the mouth's corner (regression: that leg counted as leaving
  // the area at the bend, so the route took the far wall or did not exist).
  const double bend = 0.1;
  const PolygonWithHoles area = testing::bentCorridorMap(bend);
  const VisibilityGraph graph(area, costOf("distance"));
  const Point2 end =
      Point2(80, 20) + 3.0 * graph.boundary().tolerance() * Point2(std::cos(bend), std::sin(bend));
  const Point2 mouth(50, 20);
  const Point2 target(10, 5);
  const double expected = (end - mouth).norm() + (mouth - target).norm();
  EXPECT_NEAR(graph.cost(end, target), expected, 1e-9);
  EXPECT_NEAR(graph.cost(target, end), expected, 1e-9);
  const std::vector<Point2> path = graph.shortestPath(end, target);
  ASSERT_EQ(path.size(), 3u);
  EXPECT_EQ(path[1], mouth);
  expectPathInside(area, path);
  EXPECT_NEAR(graph.costMatrix({end}, {target})[0], expected, 1e-9);
}

TEST(VisibilityGraph, BoundaryPointInAWallSpikesSliverIsReachable) {
  // Near the tip of a thin wall spike, on its left side and within the tolerance of its
  // right side: the only node is the tip; every free direction must stay open
  // (regression: the point saw nothing, or only the tip, and went round it or nowhere).
  const double half_base = 0.003;
  const PolygonWithHoles area = testing::wallSpikeMap(half_base);
  const VisibilityGraph graph(area, costOf("distance"));
  ASSERT_EQ(graph.nodeCount(), 1u);
  const double tolerance = graph.boundary().tolerance();
  const Point2 tip(5, 6);
  const Point2 down_left = (Point2(5 - half_base, 0) - tip).normalized();
  const Point2 into_wall(-down_left.y(), down_left.x());
  const double apex = 2.0 * std::atan2(half_base, 6.0);
  for (const Point2& end : {Point2(tip + 2.0 * tolerance * down_left + 1e-13 * into_wall),
                            Point2(tip + 0.5 * tolerance / std::sin(apex) * down_left)}) {
    // The wall spike is a cone from the tip: every point outside it is in sight.
    for (const Point2& target : {Point2(1, 5), Point2(9, 5), Point2(5, 9), Point2(1, 1),
                                 Point2(4.99, 0.1), Point2(5.01, 0.1)}) {
      SCOPED_TRACE(::testing::Message() << end.transpose() << " to " << target.transpose());
      EXPECT_NEAR(graph.cost(end, target), (end - target).norm(), 1e-9);
      const std::vector<Point2> path = graph.shortestPath(end, target);
      EXPECT_EQ(path.size(), 2u);
      expectPathInside(area, path);
    }
  }
}

TEST(VisibilityGraph, BoundaryPointsOfJaggedPolygonsAreReachable) {
  // Sweep lane ends lie on the offset free area's boundary up to rounding, often just past
  // a corner or inside a sharp corner's sliver: on jagged star hulls around a hole (some
  // wall-offset, as the planner makes them; some 2 m across, where a rounding error is
  // relatively larger), every such point must reach an interior point along an inside
  // route whose cost the route itself confirms.
  std::mt19937 rng(17);
  const SegmentCost distance = costOf("distance");
  int points_checked = 0;
  for (int map_index = 0; map_index < 16; ++map_index) {
    const int vertices = std::uniform_int_distribution<int>(20, 300)(rng);
    PolygonWithHoles area = testing::jaggedStarMap(rng, vertices, map_index % 2 == 0 ? 20.0 : 70.0);
    if (map_index % 3 == 2) {
      const double wall_distance = std::uniform_real_distribution<double>(0.3, 2.0)(rng);
      area = computeOffsetFreeArea(area, wall_distance).parts.front();
    }
    const double scale = map_index % 4 == 3 ? 0.01 : 1.0;
    for (Point2& p : area.hull) p *= scale;
    for (Ring& hole : area.holes)
      for (Point2& p : hole) p *= scale;
    SCOPED_TRACE("jagged map " + std::to_string(map_index));
    const VisibilityGraph graph(area, distance);
    std::uniform_real_distribution<double> coordinate(-100.0 * scale, 100.0 * scale);
    Point2 target(coordinate(rng), coordinate(rng));
    while (!contains(area, target)) target = Point2(coordinate(rng), coordinate(rng));
    const double inside_tolerance = 1e-6 * scale;
    for (const Point2& p : testing::boundaryPoints(rng, area, graph.boundary().tolerance(), 300)) {
      ++points_checked;
      const double cost = graph.cost(p, target);
      ASSERT_TRUE(std::isfinite(cost)) << std::setprecision(17) << p.transpose();
      const std::vector<Point2> path = graph.shortestPath(p, target);
      ASSERT_GE(path.size(), 2u);
      EXPECT_EQ(path.front(), p);
      EXPECT_EQ(path.back(), target);
      for (std::size_t i = 1; i < path.size(); ++i) {
        EXPECT_TRUE(segmentInside(area, path[i - 1], path[i], inside_tolerance))
            << std::setprecision(17) << p.transpose() << ": leg " << i;
      }
      EXPECT_NEAR(pathLength(path), cost, 1e-9 * (1.0 + cost));
      EXPECT_GE(cost, (target - p).norm() - 1e-12);
    }
  }
  EXPECT_EQ(points_checked, 16 * 300);
}

TEST(VisibilityGraph, DegenerateQueries) {
  const VisibilityGraph graph(squareWithHole(), costOf("waypoints"));
  EXPECT_EQ(graph.shortestPath({1, 1}, {1, 1}), std::vector<Point2>{Point2(1, 1)});
  EXPECT_EQ(graph.cost({1, 1}, {1, 1}), 0.0);
  EXPECT_EQ(graph.cost({1, 5}, {9, 5}), 3.0);
  EXPECT_THROW(graph.shortestPath({5, 5}, {1, 1}), InvalidInputError);
  EXPECT_THROW(graph.cost({1, 1}, {11, 1}), InvalidInputError);
  EXPECT_THROW(graph.costMatrix({{1, 1}}, {{1, 1}, {-3, 1}}), InvalidInputError);
  try {
    graph.cost({1, 1}, {11, 2});
  } catch (const InvalidInputError& error) {
    EXPECT_NE(std::string(error.what()).find("(11, 2)"), std::string::npos) << error.what();
  }
  EXPECT_THROW(graph.cost({std::nan(""), 1}, {1, 1}), InvalidInputError);
  EXPECT_TRUE(graph.costMatrix({}, {{1, 1}}).empty());
  // With a cache: the same answers and errors, and a refused point is not kept.
  VisibilityGraph::PointCache cache;
  EXPECT_EQ(graph.shortestPath({1, 1}, {1, 1}, &cache), std::vector<Point2>{Point2(1, 1)});
  EXPECT_EQ(graph.cost({1, 5}, {9, 5}, &cache), 3.0);
  EXPECT_THROW(graph.shortestPath({5, 5}, {1, 1}, &cache), InvalidInputError);
  EXPECT_THROW(graph.cost({1, 1}, {11, 1}, &cache), InvalidInputError);
  EXPECT_THROW(graph.cost({1, 1}, {11, 1}, &cache), InvalidInputError);
  EXPECT_EQ(graph.cost({9, 5}, {1, 5}, &cache), 3.0);
}

TEST(VisibilityGraph, ConvexAreaHasNoNodes) {
  const PolygonWithHoles triangle{{{0, 0}, {4, 0}, {0, 3}}, {}};
  const VisibilityGraph graph(triangle, costOf("distance"));
  EXPECT_EQ(graph.nodeCount(), 0u);
  EXPECT_NEAR(graph.cost({0, 0}, {4, 0}), 4.0, 1e-12);
  EXPECT_NEAR(graph.cost({4, 0}, {0, 3}), 5.0, 1e-12);
  const std::vector<double> matrix = graph.costMatrix({{0, 0}, {1, 1}}, {{4, 0}, {1, 1}});
  ASSERT_EQ(matrix.size(), 4u);
  EXPECT_NEAR(matrix[0], 4.0, 1e-12);
  EXPECT_NEAR(matrix[3], 0.0, 1e-12);
}

TEST(VisibilityGraph, RejectsDegenerateArea) {
  EXPECT_THROW(VisibilityGraph(PolygonWithHoles{{{0, 0}, {1, 1}}, {}}, costOf("distance")),
               InvalidInputError);
}

/// Properties on one random map, for one cost function.
/// Checks the routes between query points on `area`; returns how many needed a detour.
int checkRandomMap(const PolygonWithHoles& area, const std::string& cost_function,
                   std::mt19937& rng, bool compare_with_brute_force) {
  const SegmentCost segment_cost = costOf(cost_function);
  VisibilityGraph graph(area, segment_cost);
  const std::vector<Point2> points = testing::queryPoints(rng, area, 14, 8, 4);
  std::unique_ptr<testing::BruteForceRouter> brute_force;
  if (compare_with_brute_force) {
    brute_force = std::make_unique<testing::BruteForceRouter>(area, points, 1e-9);
  }
  std::vector<std::size_t> ids;
  for (const Point2& p : points) ids.push_back(graph.addQueryPoint(p));
  VisibilityGraph::PointCache cache;
  const std::vector<double> matrix = graph.costMatrix(points, points);
  const double scale = 1e-9 * 200.0;
  int detours = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (std::size_t j = 0; j < points.size(); ++j) {
      const Point2& a = points[i];
      const Point2& b = points[j];
      const std::vector<Point2> path = graph.shortestPath(a, b);
      const double cost = graph.cost(a, b);
      if (path.empty()) {
        ADD_FAILURE() << "empty path";
        continue;
      }
      detours += path.size() > 2;
      // The cache locates each point once and answers bit for bit as the graph does.
      EXPECT_EQ(graph.cost(a, b, &cache), cost);
      EXPECT_EQ(graph.shortestPath(a, b, &cache), path);
      EXPECT_EQ(path.front(), a);
      EXPECT_EQ(path.back(), b);
      expectPathInside(area, path);
      EXPECT_NEAR(segment_cost.pathCost(path), cost, scale * (1 + cost)) << cost_function;
      EXPECT_NEAR(matrix[i * points.size() + j], cost, scale * (1 + cost)) << cost_function;
      EXPECT_NEAR(graph.queryCost(ids[i], ids[j]), cost, scale * (1 + cost)) << cost_function;
      EXPECT_NEAR(segment_cost.pathCost(graph.queryPath(ids[i], ids[j])), cost, scale * (1 + cost));
      EXPECT_NEAR(graph.cost(b, a), cost, scale * (1 + cost)) << cost_function;
      const double straight = segment_cost.of(a, b);
      EXPECT_GE(cost, straight - scale * (1 + cost));
      if (graph.visible(a, b)) EXPECT_NEAR(cost, straight, scale * (1 + cost));
      if (brute_force != nullptr && i < j) {
        EXPECT_NEAR(cost, brute_force->distance(i, j), 1e-6 * (1 + cost))
            << a.transpose() << " to " << b.transpose();
      }
    }
  }
  return detours;
}

TEST(VisibilityGraph, RandomStarMapsHaveConsistentInsideRoutes) {
  std::mt19937 rng(2024);
  int detours = 0;
  for (int map_index = 0; map_index < 12; ++map_index) {
    const PolygonWithHoles area = testing::randomMap(rng, 100.0, 15, 1.0);
    SCOPED_TRACE("star map " + std::to_string(map_index));
    detours += checkRandomMap(area, "distance", rng, true);
    detours += checkRandomMap(area, map_index % 2 == 0 ? "time" : "waypoints", rng, false);
  }
  EXPECT_GT(detours, 500);
}

TEST(VisibilityGraph, RandomConvexHoleMapsHaveConsistentInsideRoutes) {
  std::mt19937 rng(99);
  int detours = 0;
  for (int map_index = 0; map_index < 12; ++map_index) {
    const PolygonWithHoles area = testing::convexHolesMap(rng, 100.0, 15, 3, 7, 0.5);
    SCOPED_TRACE("convex-hole map " + std::to_string(map_index));
    detours += checkRandomMap(area, "distance", rng, true);
    detours += checkRandomMap(area, map_index % 2 == 0 ? "waypoints" : "time", rng, false);
  }
  EXPECT_GT(detours, 500);
}

/// The all-pairs node costs are computed on one triangle and mirrored: they must be
/// symmetric bit for bit, zero on the diagonal, and closed under the triangle inequality
/// (what Floyd-Warshall and Dijkstra leave).
void expectSymmetricShortestNodeCosts(const VisibilityGraph& graph) {
  const std::size_t n = graph.nodeCount();
  for (std::size_t u = 0; u < n; ++u) {
    EXPECT_EQ(graph.nodeCost(u, u), 0.0);
    for (std::size_t w = 0; w < n; ++w) {
      ASSERT_EQ(graph.nodeCost(u, w), graph.nodeCost(w, u)) << u << " " << w;
      for (std::size_t k = 0; k < n; k += 7) {
        const double via = graph.nodeCost(u, k) + graph.nodeCost(k, w);
        EXPECT_LE(graph.nodeCost(u, w), via * (1.0 + 1e-12)) << u << " " << k << " " << w;
      }
    }
  }
}

/// Visible node pairs of the graph as a share of all pairs.
double density(const VisibilityGraph& graph) {
  const double n = static_cast<double>(graph.nodeCount());
  return static_cast<double>(graph.edgeCount()) / (0.5 * n * (n - 1.0));
}

// Random maps with hundreds of nodes: dense graphs, their costs by Floyd-Warshall.
TEST(VisibilityGraph, NodeCostsAreSymmetricBitForBitAndShortest) {
  std::mt19937 rng(77);
  for (int map_index = 0; map_index < 4; ++map_index) {
    const PolygonWithHoles area = testing::randomMap(rng, 100.0, 40, 1.0);
    const VisibilityGraph graph(area, costOf(map_index % 2 == 0 ? "distance" : "time"));
    ASSERT_GT(graph.nodeCount(), 20u);
    EXPECT_GE(density(graph), VisibilityGraph::kSparseDensity);
    expectSymmetricShortestNodeCosts(graph);
  }
}

// Dijkstra from every node and Floyd-Warshall give the same cheapest costs, up to
// rounding, on dense random maps and on lakes strewn with islands.
TEST(VisibilityGraph, DijkstraAndFloydWarshallAgree) {
  std::mt19937 rng(31);
  for (int map_index = 0; map_index < 6; ++map_index) {
    const PolygonWithHoles area = map_index % 2 == 0
                                      ? testing::randomMap(rng, 100.0, 40, 1.0)
                                      : testing::convexHolesMap(rng, 100.0, 60, 4, 6, 0.5);
    const SegmentCost cost = costOf(map_index % 3 == 0 ? "time" : "distance");
    const VisibilityGraph floyd(area, cost, VisibilityGraph::AllPairs::kFloydWarshall);
    const VisibilityGraph dijkstra(area, cost, VisibilityGraph::AllPairs::kDijkstra);
    ASSERT_EQ(floyd.nodeCount(), dijkstra.nodeCount());
    ASSERT_GT(floyd.nodeCount(), 20u);
    expectSymmetricShortestNodeCosts(dijkstra);
    for (std::size_t u = 0; u < floyd.nodeCount(); ++u) {
      for (std::size_t w = 0; w < floyd.nodeCount(); ++w) {
        const double expected = floyd.nodeCost(u, w);
        if (std::isinf(expected)) {
          ASSERT_EQ(dijkstra.nodeCost(u, w), expected) << u << " " << w;
        } else {
          ASSERT_NEAR(dijkstra.nodeCost(u, w), expected, 1e-12 * (1.0 + expected)) << u << " " << w;
        }
      }
    }
  }
}

// A noisy shoreline's reflex corners mostly face into the wall: with a cost that grows
// with length, only the node pairs whose line is tangent to the walls at both nodes are
// edges (under half the pairs that see each other), and the routes stay the
// shortest of brute force over every vertex pair; with "waypoints" every visible pair is.
TEST(VisibilityGraph, OnlyPairsTangentAtBothNodesAreEdgesWhereCostsGrowWithLength) {
  std::mt19937 rng(41);
  const PolygonWithHoles area = testing::jaggedStarMap(rng, 150, 80.0);
  const VisibilityGraph tangent(area, costOf("distance"));
  const VisibilityGraph every(area, costOf("waypoints"));
  ASSERT_EQ(tangent.nodeCount(), every.nodeCount());
  ASSERT_GT(tangent.nodeCount(), 50u);
  std::size_t visible_pairs = 0;
  for (std::size_t u = 0; u < every.nodeCount(); ++u) {
    for (std::size_t w = u + 1; w < every.nodeCount(); ++w) {
      visible_pairs += every.visible(every.node(u), every.node(w));
    }
  }
  EXPECT_EQ(every.edgeCount(), visible_pairs);
  EXPECT_LT(2 * tangent.edgeCount(), visible_pairs);
  const std::vector<Point2> points = testing::queryPoints(rng, area, 12, 12, 6);
  const testing::BruteForceRouter brute_force(area, points, 1e-9);
  int detours = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (std::size_t j = i + 1; j < points.size(); ++j) {
      const double cost = tangent.cost(points[i], points[j]);
      EXPECT_NEAR(cost, brute_force.distance(i, j), 1e-6 * (1 + cost));
      const std::vector<Point2> path = tangent.shortestPath(points[i], points[j]);
      expectPathInside(area, path);
      detours += path.size() > 2;
    }
  }
  EXPECT_GT(detours, 100);
}

TEST(VisibilityGraph, CheckerboardOfHolesTouchingAtCorners) {
  // Square holes touching diagonally: every inner corner is a pinch point that routes
  // may pass through; compared with brute force over all vertices.
  PolygonWithHoles area;
  area.hull = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  for (int i = 2; i < 8; ++i) {
    for (int j = 2; j < 8; ++j) {
      if ((i + j) % 2 != 0) continue;
      area.holes.push_back(
          {{double(i), double(j)}, {double(i), j + 1.0}, {i + 1.0, j + 1.0}, {i + 1.0, double(j)}});
    }
  }
  std::mt19937 rng(3);
  int detours = 0;
  for (int round = 0; round < 3; ++round) {
    detours += checkRandomMap(area, "distance", rng, true);
    detours += checkRandomMap(area, "waypoints", rng, false);
  }
  EXPECT_GT(detours, 100);
  const VisibilityGraph graph(area, costOf("distance"));
  // Straight along a diagonal of pinch points, from free square to free square.
  EXPECT_EQ(graph.shortestPath({2.5, 3.5}, {6.5, 7.5}).size(), 2u);
  EXPECT_NEAR(graph.cost({2.5, 3.5}, {6.5, 7.5}), 4.0 * std::sqrt(2.0), 1e-12);
}

TEST(VisibilityGraph, TimingOfTheTransitionMatrix) {
  // The planner's load: ~800 sweep patterns on a 100 m map with 15 holes of 4-7
  // vertices, so ~1600 distinct points and ~640 000 costs. Printed, not asserted.
  std::mt19937 rng(5);
  const PolygonWithHoles area = testing::convexHolesMap(rng, 100.0, 15, 4, 7, 1.0);
  ASSERT_EQ(area.holes.size(), 15u);
  const std::vector<Point2> points = testing::queryPoints(rng, area, 800, 800, 0);
  const std::vector<Point2> sources(points.begin(), points.begin() + 800);
  const std::vector<Point2> targets(points.begin() + 800, points.end());
  // Processor time, so that other processes on the machine do not count.
  const std::clock_t t0 = std::clock();
  const VisibilityGraph graph(area, costOf("time"));
  const std::clock_t t1 = std::clock();
  const std::vector<double> matrix = graph.costMatrix(sources, targets);
  const std::clock_t t2 = std::clock();
  const std::vector<double> square = graph.costMatrix(sources, sources);
  const std::clock_t t3 = std::clock();
  for (int i = 0; i < 2000; ++i) graph.shortestPath(sources[i % 800], sources[(i * 7 + 3) % 800]);
  const std::clock_t t4 = std::clock();
  auto ms = [](std::clock_t from, std::clock_t to) {
    return 1e3 * static_cast<double>(to - from) / CLOCKS_PER_SEC;
  };
  std::cout << "[ timing ] " << graph.nodeCount() << " nodes, graph " << ms(t0, t1) << " ms; "
            << matrix.size() << " costs between " << sources.size() + targets.size() << " points "
            << ms(t1, t2) << " ms; " << square.size() << " costs among " << sources.size()
            << " points " << ms(t2, t3) << " ms; 2000 single shortestPath queries " << ms(t3, t4)
            << " ms (processor time)" << std::endl;
  EXPECT_EQ(matrix.size(), 640000u);
  for (double c : matrix) ASSERT_TRUE(std::isfinite(c));
}

TEST(VisibilityGraph, TimingOfALargeHull) {
  // A lake-like star hull with 2000 vertices: about half of them are reflex nodes.
  std::mt19937 rng(8);
  PolygonWithHoles area;
  area.hull = testing::randomStarRing(rng, {0, 0}, 180.0, 200.0, 2000);
  const std::clock_t t0 = std::clock();
  const VisibilityGraph graph(area, costOf("time"));
  const std::clock_t t1 = std::clock();
  std::cout << "[ timing ] " << area.hull.size() << "-vertex hull, " << graph.nodeCount()
            << " nodes, graph " << 1e3 * static_cast<double>(t1 - t0) / CLOCKS_PER_SEC
            << " ms (processor time)" << std::endl;
  EXPECT_GT(graph.nodeCount(), 100u);
}

// HardMapGenerator star seed 315 (a hexagon, wall distance 1.98 m, trapezoidal cells): the
// offset free area is convex, so the graph has no nodes, and a corner lane's two ends lie
// up to 5.3e-8 m from the corner (within the 1e-7 m tolerance), one of them just beyond
// it. The ends' vertex judged the directions from the ends rather than from itself, so
// the lane between them and the leg from it along the edge to the next corner counted
// as leaving the area: no route, an infinite transition cost, and the planner rejected
// the mission as invalid input.
TEST(VisibilityGraph, EndsWithinTheToleranceOfAConvexCornerSeeEachOtherAndAlongItsEdges) {
  const PolygonWithHoles area = {{{-41.633258015170924, 40.448798505538107},
                                  {-45.848528789922568, -35.994888224374279},
                                  {-3.084838743997544, -52.645236683285759},
                                  {37.643276043991634, -37.736867673044834},
                                  {46.469845138768456, 13.37838337821314},
                                  {-16.308661860459683, 47.668309262539175}},
                                 {}};
  const VisibilityGraph graph(area, costOf("distance"));
  ASSERT_EQ(graph.nodeCount(), 0u);
  const Point2 beyond_corner(-3.0848387692335386, -52.645236729488197);
  const Point2 inside_corner(-3.0848387248965228, -52.645236634227921);
  const Point2 next_corner(-45.848528786872791, -35.994888169066769);
  EXPECT_TRUE(std::isfinite(graph.cost(beyond_corner, inside_corner)));
  EXPECT_TRUE(std::isfinite(graph.cost(inside_corner, beyond_corner)));
  EXPECT_NEAR(graph.cost(beyond_corner, next_corner), (next_corner - beyond_corner).norm(), 1e-9);
  EXPECT_NEAR(graph.cost(next_corner, beyond_corner), (next_corner - beyond_corner).norm(), 1e-9);
}

/// Checks an on-demand graph of `area` against the all-pairs one: every route is a path
/// inside the area whose cost it reports, at least the cheapest cost; the point cache, the
/// cost matrix and costsFrom agree with it. Returns the ratio of the routes' total cost to
/// the cheapest routes' total.
double checkOnDemandRoutes(const PolygonWithHoles& area, const std::string& cost_function,
                           std::mt19937& rng) {
  const SegmentCost segment_cost = costOf(cost_function);
  const VisibilityGraph exact(area, segment_cost, VisibilityGraph::AllPairs::kDijkstra);
  const VisibilityGraph local(area, segment_cost, VisibilityGraph::AllPairs::kOnDemand);
  EXPECT_TRUE(local.onDemand());
  EXPECT_FALSE(exact.onDemand());
  EXPECT_TRUE(std::isinf(exact.localRadius()));
  EXPECT_GT(local.localRadius(), 0.0);
  EXPECT_EQ(local.nodeCount(), exact.nodeCount());
  EXPECT_LE(local.edgeCount(), exact.edgeCount());
  const std::vector<Point2> points = testing::queryPoints(rng, area, 12, 8, 4);
  const std::vector<double> matrix = local.costMatrix(points, points);
  const VisibilityGraph::LocatedPoints located = local.locateAll(points);
  std::vector<std::size_t> every(points.size());
  std::iota(every.begin(), every.end(), 0);
  VisibilityGraph::PointCache cache;
  double total = 0.0;
  double cheapest_total = 0.0;
  const double scale = 1e-9 * 200.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::vector<double> row = local.costsFrom(located, i, every);
    for (std::size_t j = 0; j < points.size(); ++j) {
      const Point2& a = points[i];
      const Point2& b = points[j];
      const double cost = local.cost(a, b);
      const std::vector<Point2> path = local.shortestPath(a, b);
      EXPECT_EQ(path.front(), a);
      EXPECT_EQ(path.back(), b);
      expectPathInside(area, path);
      EXPECT_NEAR(segment_cost.pathCost(path), cost, scale * (1 + cost)) << cost_function;
      EXPECT_EQ(local.cost(a, b, &cache), cost);
      EXPECT_EQ(local.shortestPath(a, b, &cache), path);
      EXPECT_NEAR(matrix[i * points.size() + j], cost, scale * (1 + cost));
      EXPECT_NEAR(row[j], cost, scale * (1 + cost));
      const double cheapest = exact.cost(a, b);
      EXPECT_GE(cost, cheapest - scale * (1 + cost)) << a.transpose() << " to " << b.transpose();
      total += cost;
      cheapest_total += cheapest;
    }
  }
  for (std::size_t u = 0; u < local.nodeCount(); u += 5) {
    for (std::size_t w = 0; w < local.nodeCount(); w += 3) {
      const double cheapest = exact.cost(exact.node(u), exact.node(w));
      EXPECT_GE(local.nodeCost(u, w), cheapest - scale * (1 + cheapest));
    }
  }
  return total / cheapest_total;
}

// On demand, routes are real paths at least as dear as the cheapest, and on maps of
// hundreds of corners within a percent of them in total (the local radius holds about
// kLocalRadiusNodes nodes).
TEST(VisibilityGraph, OnDemandRoutesArePathsOfTheirCostNearTheCheapest) {
  std::mt19937 rng(2027);
  for (int map_index = 0; map_index < 6; ++map_index) {
    const PolygonWithHoles area = map_index % 2 == 0
                                      ? testing::convexHolesMap(rng, 200.0, 80, 4, 7, 0.5)
                                      : testing::randomMap(rng, 100.0, 40, 1.0);
    SCOPED_TRACE("map " + std::to_string(map_index));
    const std::string cost_function = map_index % 3 == 0 ? "time" : "distance";
    const double ratio = checkOnDemandRoutes(area, cost_function, rng);
    EXPECT_LE(ratio, 1.01) << cost_function;
  }
}

// Two groups of holes far apart along a corridor, with a wall between them that no
// straight line passes: the local radius of the group's spacing leaves the graph in two
// parts, so it grows until the nodes are joined, and every route is found.
TEST(VisibilityGraph, OnDemandRadiusGrowsUntilTheNodesAreJoined) {
  PolygonWithHoles area;
  area.hull = {{0, 0}, {1000, 0}, {1000, 40}, {0, 40}};
  auto square = [](double x, double y, double half) {
    return Ring{
        {x - half, y - half}, {x - half, y + half}, {x + half, y + half}, {x + half, y - half}};
  };
  for (int k = 0; k < 6; ++k) {
    area.holes.push_back(square(10.0 + 6.0 * k, 10.0, 1.0));
    area.holes.push_back(square(10.0 + 6.0 * k, 30.0, 1.0));
    area.holes.push_back(square(960.0 + 6.0 * k, 10.0, 1.0));
    area.holes.push_back(square(960.0 + 6.0 * k, 30.0, 1.0));
  }
  area.holes.push_back({{500, 1}, {500, 39}, {502, 39}, {502, 1}});  // the wall
  const SegmentCost distance = costOf("distance");
  const VisibilityGraph local(area, distance, VisibilityGraph::AllPairs::kOnDemand);
  const VisibilityGraph exact(area, distance);
  EXPECT_GT(local.localRadius(), 400.0);
  for (const auto& [a, b] : std::vector<std::pair<Point2, Point2>>{
           {{5, 20}, {995, 20}}, {{25, 10 - 2}, {975, 30 + 2}}, {{1, 1}, {999, 39}}}) {
    const std::vector<Point2> path = local.shortestPath(a, b);
    expectPathInside(area, path);
    EXPECT_NEAR(distance.pathCost(path), local.cost(a, b), 1e-9);
    EXPECT_NEAR(local.cost(a, b), exact.cost(a, b), 1e-6 * exact.cost(a, b));
  }
}

// A large graph is searched on demand by default; a small one keeps its table.
TEST(VisibilityGraph, ByDensityChoosesOnDemandForLargeGraphsOnly) {
  std::mt19937 rng(12);
  const PolygonWithHoles small = testing::convexHolesMap(rng, 100.0, 15, 4, 7, 1.0);
  EXPECT_FALSE(VisibilityGraph(small, costOf("distance")).onDemand());
  PolygonWithHoles large;
  large.hull = {{0, 0}, {2000, 0}, {2000, 2000}, {0, 2000}};
  for (int row = 0; row < 40; ++row) {
    for (int column = 0; column < 30; ++column) {
      const double x = 20.0 + 50.0 * column;
      const double y = 20.0 + 49.0 * row;
      large.holes.push_back({{x, y}, {x, y + 4}, {x + 4, y + 4}, {x + 4, y}});
    }
  }
  const VisibilityGraph graph(large, costOf("distance"));
  ASSERT_GT(graph.nodeCount(), VisibilityGraph::kOnDemandNodes);
  EXPECT_TRUE(graph.onDemand());
  const std::vector<Point2> path = graph.shortestPath({1, 1}, {1999, 1999});
  expectPathInside(large, path);
}

}  // namespace
}  // namespace kinematic_coverage::core
