#include "coverage_system/planner/lazy_transition_costs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <random>
#include <string>

#include "coverage_system/parameters/stage_options.h"
#include "test/route/route_test_maps.h"

namespace kinematic_coverage::core {
namespace {

/// A random instance over a map with holes: node 0 the start, 1 the goal, then `cells`
/// clusters of four patterns (random ends inside the map, a random cost of entering), with
/// the exact costs of every edge beside it.
struct LazyCase {
  PolygonWithHoles area;
  std::vector<Point2> sources;
  std::vector<Point2> targets;
  std::vector<double> entering;
  GtspInstance instance;
  std::vector<double> exact;  ///< node_count^2, row-major, 0 where no edge is

  double exactCost(const std::vector<int>& tour) const {
    double total = 0.0;
    for (std::size_t i = 0; i + 1 < tour.size(); ++i) {
      total += exact[static_cast<std::size_t>(tour[i]) * instance.node_count + tour[i + 1]];
    }
    return total;
  }
};

SegmentCost costOf(const std::string& cost_function) {
  PlannerParameters parameters;
  parameters.cost_function = cost_function;
  return SegmentCost(segmentCostOf(parameters));
}

SegmentCost timeCost() { return costOf("time"); }

LazyCase randomCase(unsigned seed, int cells, const SegmentCost& segment_cost,
                    const VisibilityGraph** graph_out,
                    std::unique_ptr<VisibilityGraph>* graph_holder) {
  std::mt19937 rng(seed);
  LazyCase c;
  c.area = testing::convexHolesMap(rng, 100.0, 15, 4, 7, 1.0);
  const std::vector<Point2> points = testing::queryPoints(rng, c.area, 2 + 8 * cells, 0, 0);
  std::uniform_real_distribution<double> entering(0.0, 50.0);
  c.sources = {points[0], points[1]};
  c.targets = {points[0], points[1]};
  c.entering = {0.0, 0.0};
  c.instance.clusters = {{0}, {1}};
  for (int k = 0; k < cells; ++k) {
    std::vector<int> cluster;
    for (int p = 0; p < 4; ++p) {
      cluster.push_back(static_cast<int>(c.sources.size()));
      c.sources.push_back(points[2 + 8 * k + 2 * p]);
      c.targets.push_back(points[3 + 8 * k + 2 * p]);
      c.entering.push_back(entering(rng));
    }
    c.instance.clusters.push_back(cluster);
  }
  const std::size_t n = c.sources.size();
  c.instance.node_count = static_cast<int>(n);
  c.instance.start_cluster = 0;
  c.instance.goal_cluster = 1;
  *graph_holder = std::make_unique<VisibilityGraph>(c.area, segment_cost);
  *graph_out = graph_holder->get();
  const std::vector<double> routes = (*graph_out)->costMatrix(c.sources, c.targets);
  c.exact.assign(n * n, 0.0);
  for (std::size_t v = 0; v < n; ++v) {
    for (std::size_t w = 1; w < n; ++w) {
      if (v != 1 && w != v) c.exact[v * n + w] = routes[v * n + w] + c.entering[w];
    }
  }
  return c;
}

constexpr double kTolerance = 1e-9;

// Edges between nearby cells, from the start and into the goal cost their route exactly;
// every other edge is estimated by a route through a landmark: never below the straight segment,
// and under the distance cost never below the edge's own route.
TEST(LazyTransitionCosts, NearbyEdgesAreExactAndTheOthersEstimatedByAPath) {
  for (unsigned seed : {1u, 2u, 3u, 4u}) {
    const bool distance = seed % 2 == 0;
    const SegmentCost segment = costOf(distance ? "distance" : "time");
    const VisibilityGraph* graph = nullptr;
    std::unique_ptr<VisibilityGraph> holder;
    LazyCase c = randomCase(seed, 40, segment, &graph, &holder);
    const LazyTransitionCosts lazy(*graph, segment, c.sources, c.targets, c.entering, &c.instance);
    EXPECT_NO_THROW(validateGtspInstance(c.instance));
    const std::size_t n = c.sources.size();
    std::size_t equal = 0;
    std::size_t edges = 0;
    for (std::size_t v = 0; v < n; ++v) {
      for (std::size_t w = 1; w < n; ++w) {
        if (v == 1 || w == v) continue;
        ++edges;
        const double exact = c.exact[v * n + w];
        const double given = c.instance.costs[v * n + w];
        // A route through a landmark is a path of the area, so never cheaper than the
        // shortest; under the time cost (a stop at every bend) a path bending once in open
        // water can beat the visibility graph's routes, which bend at corners only.
        const double floor =
            distance ? exact : segment.of(c.sources[v], c.targets[w]) + c.entering[w];
        EXPECT_GE(given, floor - kTolerance * (1.0 + exact)) << v << " -> " << w;
        if (v == 0 || w == 1) EXPECT_NEAR(given, exact, kTolerance * (1.0 + exact));
        equal += std::abs(given - exact) <= kTolerance * (1.0 + exact);
      }
    }
    EXPECT_GE(equal, lazy.exactCount());
    EXPECT_LT(lazy.exactCount(), edges);  // 40 cells: not all of them candidates
    EXPECT_GT(lazy.exactCount(), edges / 4);
  }
}

// makeExact prices every estimated edge that the tour uses: the tour it returns costs
// exactly its edges' routes, and no more than the tour it was given.
TEST(LazyTransitionCosts, MadeExactATourCostsItsRoutesAndNoMoreThanBefore) {
  for (unsigned seed : {4u, 5u, 6u}) {
    const VisibilityGraph* graph = nullptr;
    std::unique_ptr<VisibilityGraph> holder;
    LazyCase c = randomCase(seed, 40, timeCost(), &graph, &holder);
    LazyTransitionCosts lazy(*graph, timeCost(), c.sources, c.targets, c.entering, &c.instance);
    // A random tour, which uses many estimated edges.
    std::mt19937 rng(seed);
    std::vector<int> order;
    for (std::size_t k = 2; k < c.instance.clusters.size(); ++k) {
      order.push_back(c.instance.clusters[k][rng() % 4]);
    }
    std::shuffle(order.begin(), order.end(), rng);
    GtspSolution random_tour;
    random_tour.nodes = {0};
    random_tour.nodes.insert(random_tour.nodes.end(), order.begin(), order.end());
    random_tour.nodes.push_back(1);
    const double before = c.exactCost(random_tour.nodes);
    const std::size_t priced = lazy.exactCount();
    const GtspSolution exact =
        lazy.makeExact(&c.instance, random_tour, std::chrono::steady_clock::time_point::max());
    EXPECT_NO_THROW(validateGtspTour(c.instance, exact.nodes));
    EXPECT_NEAR(exact.cost, c.exactCost(exact.nodes), kTolerance * exact.cost);
    EXPECT_LE(exact.cost, before * (1.0 + kTolerance));
    EXPECT_GT(lazy.exactCount(), priced);
  }
}

// With no more cells than the candidates, every edge is exact: the generalized TSP's
// exact solver then finds the optimum of the exact costs.
TEST(LazyTransitionCosts, FewCellsAreAllExactAndSolvedToTheOptimum) {
  const VisibilityGraph* graph = nullptr;
  std::unique_ptr<VisibilityGraph> holder;
  LazyCase c = randomCase(7, 8, timeCost(), &graph, &holder);
  GtspInstance exact_instance = c.instance;
  exact_instance.costs = c.exact;
  LazyTransitionCosts lazy(*graph, timeCost(), c.sources, c.targets, c.entering, &c.instance);
  // Every edge between clusters (an edge within one is never in a tour).
  std::vector<int> cluster_of(c.sources.size());
  for (std::size_t k = 0; k < c.instance.clusters.size(); ++k) {
    for (int v : c.instance.clusters[k]) cluster_of[v] = static_cast<int>(k);
  }
  const std::size_t n = c.sources.size();
  for (std::size_t v = 0; v < n; ++v) {
    for (std::size_t w = 0; w < n; ++w) {
      if (cluster_of[v] == cluster_of[w]) continue;
      const double exact = c.exact[v * n + w];
      EXPECT_NEAR(c.instance.costs[v * n + w], exact, kTolerance * (1.0 + exact));
    }
  }
  GtspOptions options;
  const GtspSolution optimum = solveGtsp(exact_instance, options);
  const GtspSolution solved = lazy.makeExact(&c.instance, solveGtsp(c.instance, options),
                                             std::chrono::steady_clock::time_point::max());
  EXPECT_NEAR(solved.cost, optimum.cost, kTolerance * optimum.cost);
}

}  // namespace
}  // namespace kinematic_coverage::core
