#include "trajectory_generation_tools/smoothing/boundary_edge_index.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "test/smoothing/smoothing_oracle.h"
#include "test/support/random_polygons.h"

namespace kinematic_coverage::core {
namespace {

TEST(BoundaryEdgeIndex, EmptyAreaIsTheFreePlane) {
  const BoundaryEdgeIndex index(PolygonWithHoles{});
  EXPECT_EQ(index.edgeCount(), 0u);
  EXPECT_TRUE(index.inside({1e9, -1e9}));
  EXPECT_TRUE(index.segmentClear({0, 0}, {5, 5}));
}

TEST(BoundaryEdgeIndex, TouchingIsACollision) {
  PolygonWithHoles area;
  area.hull = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const BoundaryEdgeIndex index(area);
  EXPECT_FALSE(index.segmentClear({1, 1}, {1, 0}));                           // ends on the hull
  EXPECT_TRUE(index.segmentClear({1, 1}, {1, 1e-6}));                         // keeps 1e-6 m
  EXPECT_FALSE(index.arcClear(PathPrimitive::arc({5, 5}, 5.0, -M_PI, 0.5)));  // tangent
  EXPECT_TRUE(index.arcClear(PathPrimitive::arc({5, 5}, 4.999, -M_PI, 0.5)));
  EXPECT_FALSE(index.inside({11, 5}));
  EXPECT_FALSE(index.inside({-1e12, 5}));
}

TEST(BoundaryEdgeIndex, AClearanceKeepsPrimitivesThatFarFromTheEdges) {
  PolygonWithHoles area;
  area.hull = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  area.holes = {{{4, 4}, {4, 6}, {6, 6}, {6, 4}}};
  const BoundaryEdgeIndex index(area, 0.5);
  EXPECT_EQ(index.clearance(), 0.5);
  EXPECT_TRUE(index.segmentClear({1, 0.6}, {3, 0.6}));   // 0.6 m from the hull
  EXPECT_FALSE(index.segmentClear({1, 0.4}, {3, 0.4}));  // 0.4 m
  EXPECT_FALSE(index.segmentClear({3.6, 1}, {3.6, 9}));  // 0.4 m from the obstacle
  // Around the obstacle, whose corners lie sqrt(2) m from its centre: 0.6 m and 0.4 m off.
  EXPECT_TRUE(index.arcClear(PathPrimitive::arc({5, 5}, std::sqrt(2.0) + 0.6, 0.0, M_PI)));
  EXPECT_FALSE(index.arcClear(PathPrimitive::arc({5, 5}, std::sqrt(2.0) + 0.4, 0.0, M_PI)));
  EXPECT_EQ(BoundaryEdgeIndex(area).clearance(), kContactTolerance);
  EXPECT_THROW(BoundaryEdgeIndex(area, -0.1), InvalidInputError);
  EXPECT_THROW(BoundaryEdgeIndex(area, std::nan("")), InvalidInputError);
}

TEST(BoundaryEdgeIndex, PiecesOnTheOffsetBoundaryKeepTheClearance) {
  // A leg exactly the clearance from the hull keeps it; within kClearanceTolerance (1 mm)
  // it still does, 2 mm nearer it does not. The contact check (clearance 0) stays strict.
  PolygonWithHoles area;
  area.hull = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const BoundaryEdgeIndex index(area, 1.0);
  EXPECT_TRUE(index.segmentClear({1, 1}, {9, 1}));
  EXPECT_TRUE(index.segmentClear({1, 0.9995}, {9, 0.9995}));
  EXPECT_FALSE(index.segmentClear({1, 0.998}, {9, 0.998}));
  EXPECT_TRUE(index.arcClear(PathPrimitive::arc({5, 5}, 4.0, 0.0, M_PI)));  // 1 m off
  EXPECT_FALSE(index.arcClear(PathPrimitive::arc({5, 5}, 4.002, 0.0, M_PI)));
  EXPECT_FALSE(BoundaryEdgeIndex(area).segmentClear({1, 0}, {9, 0}));
}

TEST(BoundaryEdgeIndex, AgreesWithBruteForceOnRandomMaps) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int blocked = 0;
  for (int map_index = 0; map_index < 50; ++map_index) {
    const PolygonWithHoles area = testing::randomMap(rng, 100.0, 8, 1.0);
    const BoundaryEdgeIndex index(area);
    for (int query = 0; query < 200; ++query) {
      const Point2 a(120 * unit(rng) - 60, 120 * unit(rng) - 60);
      const Point2 b = a + Point2(20 * unit(rng) - 10, 20 * unit(rng) - 10);
      EXPECT_EQ(index.inside(a), testing::inFreeArea(area, a));
      EXPECT_EQ(index.segmentClear(a, b),
                testing::segmentClearance(area, a, b) > kContactTolerance);
      const double r = 0.2 + 5 * unit(rng);
      const PathPrimitive arc =
          PathPrimitive::arc(a, r, 2 * M_PI * unit(rng), 4 * M_PI * unit(rng) - 2 * M_PI);
      // arcClear is about contact with edges; containment is inside()'s question.
      if (!testing::inFreeArea(area, arc.start())) continue;
      const double spacing = 1e-3 * r;
      const double sampled = testing::sampledArcClearance(area, arc, spacing);
      const bool clear = index.arcClear(arc);
      if (sampled > 0.5 * spacing) EXPECT_TRUE(clear) << map_index << " " << query;
      if (sampled <= kContactTolerance) EXPECT_FALSE(clear) << map_index << " " << query;
      if (!clear) ++blocked;
    }
  }
  EXPECT_GT(blocked, 300);
}

}  // namespace
}  // namespace kinematic_coverage::core
