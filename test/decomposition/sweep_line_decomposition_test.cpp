#include "polygon_coverage_ros_bridge/decomposition/sweep_line_decomposition.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "polygon_coverage_ros_bridge/decomposition/sweep_direction.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "test/support/random_polygons.h"

namespace kinematic_coverage::core {
namespace {

/// The properties every decomposition must have: the cells tile the area (areas add
/// up, every cell inside it), and each is CCW and monotone for the direction.
void expectValidDecomposition(const PolygonWithHoles& region, const std::vector<Ring>& cells,
                              double direction) {
  ASSERT_FALSE(cells.empty());
  double total = 0.0;
  for (const Ring& cell : cells) {
    EXPECT_GT(signedArea(cell), 0.0);
    EXPECT_TRUE(isMonotone(cell, direction));
    total += signedArea(cell);
    for (std::size_t i = 0; i < cell.size(); ++i) {
      const Point2 mid = 0.5 * (cell[i] + cell[(i + 1) % cell.size()]);
      EXPECT_TRUE(contains(region, mid, 1e-7)) << mid.transpose();
    }
  }
  EXPECT_NEAR(total, area(region), 1e-7 * std::max(1.0, area(region)));
}

const PolygonWithHoles kSquareWithHole = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                                          {{{4, 4}, {4, 6}, {6, 6}, {6, 4}}}};

TEST(SweepLineDecomposition, SquareWithHoleBoustrophedonHasFourCells) {
  const SweepLineDecomposition decomposition(DecompositionType::kBoustrophedon);
  const auto cells = decomposition.decompose(kSquareWithHole, M_PI / 2);
  EXPECT_EQ(cells.size(), 4u);
  expectValidDecomposition(kSquareWithHole, cells, M_PI / 2);
}

TEST(SweepLineDecomposition, ConvexPolygonIsOneBoustrophedonCell) {
  const PolygonWithHoles hexagon = {{{0, 0}, {4, -1}, {8, 0}, {9, 3}, {4, 6}, {-1, 3}}, {}};
  const SweepLineDecomposition boustrophedon(DecompositionType::kBoustrophedon);
  const SweepLineDecomposition trapezoidal(DecompositionType::kTrapezoidal);
  for (double direction : {0.0, 0.4, M_PI / 2, 2.0}) {
    const auto cells = boustrophedon.decompose(hexagon, direction);
    EXPECT_EQ(cells.size(), 1u);
    expectValidDecomposition(hexagon, cells, direction);
    const auto trapezoids = trapezoidal.decompose(hexagon, direction);
    EXPECT_GE(trapezoids.size(), 1u);
    expectValidDecomposition(hexagon, trapezoids, direction);
  }
}

TEST(SweepLineDecomposition, TrapezoidalSplitsAtEveryVertex) {
  const SweepLineDecomposition trapezoidal(DecompositionType::kTrapezoidal);
  // Lanes vertical: vertical lines through the 4 hole vertices split the square
  // into left, right, and below/above the hole: 4 trapezoids.
  const auto cells = trapezoidal.decompose(kSquareWithHole, M_PI / 2);
  EXPECT_EQ(cells.size(), 4u);
  const PolygonWithHoles pentagon = {{{0, 0}, {10, 0}, {10, 10}, {5, 12}, {0, 10}}, {}};
  EXPECT_EQ(trapezoidal.decompose(pentagon, M_PI / 2).size(), 2u);
}

TEST(SweepLineDecomposition, UShapeSplitsAtCriticalPoint) {
  const PolygonWithHoles u = {{{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}, {}};
  const SweepLineDecomposition decomposition(DecompositionType::kBoustrophedon);
  const auto vertical_lanes = decomposition.decompose(u, M_PI / 2);
  EXPECT_EQ(vertical_lanes.size(), 1u);
  expectValidDecomposition(u, vertical_lanes, M_PI / 2);
  const auto horizontal_lanes = decomposition.decompose(u, 0.0);
  EXPECT_EQ(horizontal_lanes.size(), 3u);
  expectValidDecomposition(u, horizontal_lanes, 0.0);
}

TEST(SweepLineDecomposition, HolesTouchingAtAPinchPoint) {
  // Two holes meeting at one vertex, lanes parallel to their shared diagonal.
  const PolygonWithHoles area = {
      {{0, 0}, {20, 0}, {20, 20}, {0, 20}},
      {{{5, 5}, {5, 10}, {10, 10}, {10, 5}}, {{10, 10}, {10, 15}, {15, 15}, {15, 10}}}};
  const SweepLineDecomposition decomposition(DecompositionType::kBoustrophedon);
  for (double direction : {0.0, M_PI / 4, M_PI / 2, 1.0}) {
    SCOPED_TRACE(direction);
    expectValidDecomposition(area, decomposition.decompose(area, direction), direction);
  }
}

TEST(SweepLineDecomposition, RandomMapsTileTheArea) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(0.0, M_PI);
  for (int trial = 0; trial < 200; ++trial) {
    const PolygonWithHoles area = testing::randomMap(rng, 100.0, 10, 1.0);
    for (auto type : {DecompositionType::kBoustrophedon, DecompositionType::kTrapezoidal}) {
      const double direction = trial % 3 == 0 ? angle(rng) : candidateDirections({area.hull}, 1)[0];
      SCOPED_TRACE(::testing::Message() << "trial " << trial << " direction " << direction);
      expectValidDecomposition(area, SweepLineDecomposition(type).decompose(area, direction),
                               direction);
    }
  }
}

TEST(SweepLineDecomposition, LongestOverlapJoinsAcrossCriticalPoints) {
  const SweepLineDecomposition joined(DecompositionType::kBoustrophedon,
                                      CellJoining::kLongestOverlap);
  // Around a hole: Choset's four cells become two (left part with the wider side of the
  // hole, the other side with the right part).
  const auto around_hole = joined.decompose(kSquareWithHole, M_PI / 2);
  EXPECT_EQ(around_hole.size(), 2u);
  expectValidDecomposition(kSquareWithHole, around_hole, M_PI / 2);
  // A U with horizontal lanes: the base goes on into one arm; the other arm is a cell.
  const PolygonWithHoles u = {{{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}, {}};
  const auto u_cells = joined.decompose(u, 0.0);
  EXPECT_EQ(u_cells.size(), 2u);
  expectValidDecomposition(u, u_cells, 0.0);
  // Trapezoidal cells are not joined.
  EXPECT_EQ(SweepLineDecomposition(DecompositionType::kTrapezoidal, CellJoining::kLongestOverlap)
                .decompose(kSquareWithHole, M_PI / 2)
                .size(),
            4u);
}

/// A shore whose small bays cut Choset's cells: a square whose top edge is a saw of
/// `teeth` teeth, each turning back across the lanes.
PolygonWithHoles sawShore(int teeth) {
  Ring hull = {{0, 0}, {100, 0}};
  const double pitch = 100.0 / teeth;
  for (int k = teeth; k > 0; --k) {
    const double x = k * pitch;
    hull.push_back({x, 50.0});
    hull.push_back({x - 0.7 * pitch, 52.0});
    hull.push_back({x - 0.5 * pitch, 50.5});
  }
  hull.push_back({0, 50.0});
  return {hull, {}};
}

TEST(SweepLineDecomposition, LongestOverlapKeepsOpenWaterOneCell) {
  const PolygonWithHoles shore = sawShore(20);
  const double lanes_across = M_PI / 2;  // vertical lanes, the sweep moves along the saw
  const auto choset =
      SweepLineDecomposition(DecompositionType::kBoustrophedon).decompose(shore, lanes_across);
  const auto joined =
      SweepLineDecomposition(DecompositionType::kBoustrophedon, CellJoining::kLongestOverlap)
          .decompose(shore, lanes_across);
  expectValidDecomposition(shore, choset, lanes_across);
  expectValidDecomposition(shore, joined, lanes_across);
  // Choset: every tooth opens a bay cell and a new cell of the open water below it.
  EXPECT_GE(choset.size(), 40u);
  // Joined: the open water is one cell under all the bays, plus one cell per bay.
  EXPECT_EQ(joined.size(), 21u);
  double largest = 0.0;
  for (const Ring& cell : joined) largest = std::max(largest, signedArea(cell));
  EXPECT_GT(largest, 100.0 * 50.0 - 1e-6);
}

TEST(SweepLineDecomposition, LongestOverlapRandomMapsTileTheArea) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> angle(0.0, M_PI);
  const SweepLineDecomposition choset(DecompositionType::kBoustrophedon);
  const SweepLineDecomposition joined(DecompositionType::kBoustrophedon,
                                      CellJoining::kLongestOverlap);
  for (int trial = 0; trial < 200; ++trial) {
    const PolygonWithHoles area = testing::randomMap(rng, 100.0, 10, 1.0);
    const double direction = trial % 3 == 0 ? angle(rng) : candidateDirections({area.hull}, 1)[0];
    SCOPED_TRACE(::testing::Message() << "trial " << trial << " direction " << direction);
    const auto cells = joined.decompose(area, direction);
    expectValidDecomposition(area, cells, direction);
    EXPECT_LE(cells.size(), choset.decompose(area, direction).size());
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
