#include "polygon_coverage_ros_bridge/geometry/edge_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// Distance between the segments [a, b] and [p, q] when they do not cross; 0 when they do.
double segmentDistance(const Point2& a, const Point2& b, const Point2& p, const Point2& q) {
  const double d1 = cross(a, b, p), d2 = cross(a, b, q);
  const double d3 = cross(p, q, a), d4 = cross(p, q, b);
  if (((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0))) return 0.0;
  return std::min({distanceToSegment(a, p, q), distanceToSegment(b, p, q),
                   distanceToSegment(p, a, b), distanceToSegment(q, a, b)});
}

struct RandomEdges {
  std::vector<Point2> starts;
  std::vector<Point2> ends;
};

RandomEdges randomEdges(std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> position(-50.0, 50.0);
  std::uniform_real_distribution<double> step(-8.0, 8.0);
  RandomEdges edges;
  for (int i = 0; i < count; ++i) {
    const Point2 start(position(rng), position(rng));
    edges.starts.push_back(start);
    edges.ends.push_back(start + Point2(step(rng), step(rng)));
  }
  return edges;
}

TEST(EdgeGrid, ASegmentVisitsEveryEdgeWithinThePadding) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> position(-60.0, 60.0);
  for (int trial = 0; trial < 20; ++trial) {
    const RandomEdges edges = randomEdges(rng, 50 + 10 * trial);
    EdgeGrid::Layout layout;
    layout.padding = 1e-6;
    layout.margin = 2e-6;
    const EdgeGrid grid(edges.starts, edges.ends, layout);
    for (int query = 0; query < 100; ++query) {
      const Point2 a(position(rng), position(rng));
      const Point2 b = query % 4 == 0 ? a : Point2(position(rng), position(rng));
      std::set<int> visited;
      grid.visitEdgesAlong(a, b, [&](int e) {
        visited.insert(e);
        return true;
      });
      for (int e = 0; e < static_cast<int>(edges.starts.size()); ++e) {
        if (segmentDistance(a, b, edges.starts[e], edges.ends[e]) <= 1e-7) {
          EXPECT_TRUE(visited.count(e)) << "trial " << trial << ", edge " << e;
        }
      }
    }
  }
}

TEST(EdgeGrid, ABoxCollectsEveryEdgeWhoseBoxItMeetsOnce) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> position(-70.0, 70.0);
  std::uniform_real_distribution<double> extent(0.0, 20.0);
  const RandomEdges edges = randomEdges(rng, 300);
  EdgeGrid::Layout layout;
  layout.cells_per_edge = 4.0;
  layout.max_cells_per_axis = 2048;
  const EdgeGrid grid(edges.starts, edges.ends, layout);
  for (int query = 0; query < 500; ++query) {
    const Point2 low(position(rng), position(rng));
    const Point2 high = low + Point2(extent(rng), extent(rng));
    std::vector<int> ids;
    grid.collect(grid.cellsOf(low, high), &ids);
    EXPECT_TRUE(std::is_sorted(ids.begin(), ids.end()));
    EXPECT_EQ(std::adjacent_find(ids.begin(), ids.end()), ids.end());
    for (int e = 0; e < static_cast<int>(edges.starts.size()); ++e) {
      const Point2 box_low = edges.starts[e].cwiseMin(edges.ends[e]);
      const Point2 box_high = edges.starts[e].cwiseMax(edges.ends[e]);
      const bool meets =
          (box_low.array() <= high.array()).all() && (low.array() <= box_high.array()).all();
      if (meets) EXPECT_TRUE(std::binary_search(ids.begin(), ids.end(), e)) << "edge " << e;
    }
  }
}

TEST(EdgeGrid, EdgesAlongOneLineAndNoEdgesAreValid) {
  // Collinear edges span a box of zero height: cells still have positive size.
  const EdgeGrid line({{0, 0}, {1, 0}}, {{1, 0}, {2, 0}}, EdgeGrid::Layout());
  std::vector<int> ids;
  line.collect(line.cellsOf({0.5, -1}, {1.5, 1}), &ids);
  EXPECT_EQ(ids, (std::vector<int>{0, 1}));
  EXPECT_TRUE(line.covers({1, 0}));
  EXPECT_FALSE(line.covers({1, 1}));

  const EdgeGrid empty({}, {}, EdgeGrid::Layout());
  empty.collect(empty.cellsOf({-1, -1}, {1, 1}), &ids);
  EXPECT_TRUE(ids.empty());
  EXPECT_TRUE(empty.visitEdgesAlong({0, 0}, {1, 1}, [](int) { return false; }));
  EXPECT_FALSE(empty.covers({0, 0}));
}

}  // namespace
}  // namespace kinematic_coverage::core
