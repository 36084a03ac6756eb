#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/internal_error.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "test/support/random_polygons.h"

namespace kinematic_coverage::core {
namespace {

/// A counter-clockwise ring of n vertices around the origin, radius 150 m, every other vertex
/// pulled 5 cm inward (reflex) when `zigzag`.
Ring circle(int n, bool zigzag) {
  Ring ring;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * M_PI * i / n;
    const double r = 150.0 - (zigzag && i % 2 == 1 ? 0.05 : 0.0);
    ring.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return ring;
}

TEST(WallOffset, ShrinksASquareByTheWallDistance) {
  const PolygonWithHoles square = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {}};
  const OffsetFreeArea offset = computeOffsetFreeArea(square, 1.0);
  ASSERT_EQ(offset.parts.size(), 1u);
  EXPECT_NEAR(area(offset.parts.front()), 64.0, 1e-9);
}

/// Holes whose grown outlines overlap each other and the hull's offset are taken away as
/// their union: two 2 m squares 1 m apart grow into one 7 m x 4 m hole, and a third one
/// 1.5 m from the shore grows into the shore's offset, a notch rather than a hole.
TEST(WallOffset, GrownHolesThatOverlapAreTakenAwayAsTheirUnion) {
  const PolygonWithHoles lake = {{{0, 0}, {20, 0}, {20, 20}, {0, 20}},
                                 {{{4, 9}, {6, 9}, {6, 11}, {4, 11}},
                                  {{7, 9}, {9, 9}, {9, 11}, {7, 11}},
                                  {{14, 1.5}, {16, 1.5}, {16, 3.5}, {14, 3.5}}}};
  const OffsetFreeArea offset = computeOffsetFreeArea(lake, 1.0);
  ASSERT_EQ(offset.parts.size(), 1u);
  EXPECT_EQ(offset.parts.front().holes.size(), 1u);
  // 18 x 18 less the merged hole [3, 10] x [8, 12] and the notch [13, 17] x [1, 4.5].
  EXPECT_NEAR(area(offset.parts.front()), 324.0 - 28.0 - 4.0 * 3.5, 1e-9);
}

/// Mitred as the reference's straight-skeleton offset: an L-shaped room's reflex corner
/// keeps a sharp corner (a rounded offset would keep (1 - pi/4) m^2 more there).
TEST(WallOffset, ReflexCornersAreMitred) {
  const PolygonWithHoles room = {{{0, 0}, {10, 0}, {10, 5}, {5, 5}, {5, 10}, {0, 10}}, {}};
  const OffsetFreeArea offset = computeOffsetFreeArea(room, 1.0);
  ASSERT_EQ(offset.parts.size(), 1u);
  EXPECT_NEAR(area(offset.parts.front()), 8.0 * 3.0 + 3.0 * 5.0, 1e-9);
  EXPECT_EQ(offset.parts.front().hull.size(), 6u);
}

/// The wall band: the distance from a point to the hull and the holes.
double wallDistance(const PolygonWithHoles& free_area, const Point2& p) {
  double least = distanceToRing(p, free_area.hull);
  for (const Ring& hole : free_area.holes) least = std::min(least, distanceToRing(p, hole));
  return least;
}

/// True when the segment a-b lies on a line parallel to a wall edge at `distance` from it.
bool parallelToAWallAt(const PolygonWithHoles& free_area, const Point2& a, const Point2& b,
                       double distance, double tolerance) {
  auto onRing = [&](const Ring& ring) {
    for (std::size_t e = 0, n = ring.size(); e < n; ++e) {
      const Point2& c = ring[e];
      const Point2 u = (ring[(e + 1) % n] - c).normalized();
      const Point2 normal(-u.y(), u.x());
      if (std::abs(std::abs(normal.dot(a - c)) - distance) <= tolerance &&
          std::abs(std::abs(normal.dot(b - c)) - distance) <= tolerance &&
          normal.dot(a - c) * normal.dot(b - c) > 0.0) {
        return true;
      }
    }
    return false;
  };
  if (onRing(free_area.hull)) return true;
  return std::any_of(free_area.holes.begin(), free_area.holes.end(), onRing);
}

/// On 40 random maps of 100 m with up to 8 holes, at three distances: the offset lies in the
/// free area at least the wall distance from every wall (no leg enters the wall band), each
/// of its edges runs parallel to a wall edge at exactly the wall distance (the mitred
/// offset: nothing of the free area is given up but the mitres' corners), and its area
/// shrinks as the distance grows.
TEST(WallOffset, OffsetsKeepTheWallDistanceAndRunParallelToTheWalls) {
  std::mt19937 rng(29);
  constexpr double kTolerance = 1e-7;
  std::size_t edges_checked = 0;
  for (int m = 0; m < 40; ++m) {
    SCOPED_TRACE("map " + std::to_string(m));
    const PolygonWithHoles map = testing::randomMap(rng, 100.0, 8, 1.0);
    const WallOffset offset(map);
    double previous_area = area(map);
    for (double distance : {0.3, 1.0, 2.5}) {
      const OffsetFreeArea result = offset.at(distance);
      ASSERT_FALSE(result.parts.empty());
      const double offset_area = area(result.parts);
      EXPECT_LT(offset_area, previous_area);
      previous_area = offset_area;
      for (const PolygonWithHoles& part : result.parts) {
        std::vector<const Ring*> rings = {&part.hull};
        for (const Ring& hole : part.holes) rings.push_back(&hole);
        for (const Ring* ring : rings) {
          for (std::size_t i = 0, n = ring->size(); i < n; ++i) {
            const Point2& a = (*ring)[i];
            const Point2& b = (*ring)[(i + 1) % n];
            ASSERT_TRUE(contains(map, a));
            ASSERT_GE(wallDistance(map, a), distance - kTolerance);
            ASSERT_GE(wallDistance(map, 0.5 * (a + b)), distance - kTolerance);
            if ((b - a).norm() > 1e-6) {
              ASSERT_TRUE(parallelToAWallAt(map, a, b, distance, kTolerance))
                  << "edge " << a.transpose() << " - " << b.transpose();
              ++edges_checked;
            }
          }
        }
      }
    }
  }
  EXPECT_GT(edges_checked, 2500u);
}

/// A noisy 6 000-vertex shore with 3 000 reflex vertices (whose straight skeleton would have
/// taken 900 MB, and was refused) is offset like any other ring.
TEST(WallOffset, ThousandsOfReflexVerticesAreOffset) {
  const PolygonWithHoles noisy = {circle(6000, true), {}};
  const OffsetFreeArea offset = computeOffsetFreeArea(noisy, 1.0);
  ASSERT_EQ(offset.parts.size(), 1u);
  // Between the circles 1 m inside the teeth's tips and 1.05 m (the mitres of the reflex
  // vertices, 5 cm deeper, reach about 1.048 m in) inside the notches.
  EXPECT_LT(area(offset.parts), M_PI * 149.0 * 149.0);
  EXPECT_GT(area(offset.parts), M_PI * 148.9 * 148.9);
  for (const Point2& p : offset.parts.front().hull) {
    EXPECT_GE(distanceToRing(p, noisy.hull), 1.0 - 1e-7);
  }
  const PolygonWithHoles round = {circle(6000, false), {}};
  EXPECT_NEAR(area(computeOffsetFreeArea(round, 1.0).parts),
              area(round) * std::pow(149.0 / 150.0, 2), 1.0);
}

void expectSameParts(const OffsetFreeArea& a, const OffsetFreeArea& b) {
  ASSERT_EQ(a.parts.size(), b.parts.size());
  for (std::size_t k = 0; k < a.parts.size(); ++k) {
    EXPECT_EQ(a.parts[k].hull, b.parts[k].hull) << "part " << k;
    EXPECT_EQ(a.parts[k].holes, b.parts[k].holes) << "part " << k;
  }
}

/// The part joiner offsets one area at many distances from one WallOffset: each offset is
/// the one computed on its own, bit for bit; a 2 m strait splits the area above 1 m.
TEST(WallOffset, OneAreaAtManyDistances) {
  std::mt19937 rng(23);
  std::vector<PolygonWithHoles> maps = {
      // Two 10 m rooms joined by a 2 m wide channel.
      {{{0, 0},
        {10, 0},
        {10, 4},
        {12, 4},
        {12, 0},
        {22, 0},
        {22, 10},
        {12, 10},
        {12, 6},
        {10, 6},
        {10, 10},
        {0, 10}},
       {}},
      {{{0, 0}, {20, 0}, {20, 20}, {0, 20}},
       {{{4, 9}, {6, 9}, {6, 11}, {4, 11}}, {{7, 9}, {9, 9}, {9, 11}, {7, 11}}}}};
  for (int k = 0; k < 6; ++k) maps.push_back(testing::randomMap(rng, 100.0, 8, 1.0));
  for (std::size_t m = 0; m < maps.size(); ++m) {
    SCOPED_TRACE("map " + std::to_string(m));
    const WallOffset offset(maps[m]);
    for (double distance : {3.0, 1.5, 0.75, 0.3, 0.02}) {
      if (m < 2 && distance > 1.5) continue;
      expectSameParts(offset.at(distance), computeOffsetFreeArea(maps[m], distance));
    }
  }
  const WallOffset strait(maps[0]);
  EXPECT_EQ(strait.at(1.5).parts.size(), 2u);
  EXPECT_EQ(strait.at(0.4).parts.size(), 1u);
  // Distance 0: the free area itself.
  ASSERT_EQ(strait.at(0.0).parts.size(), 1u);
  EXPECT_NEAR(area(strait.at(0.0).parts), area(maps[0]), 1e-9);
  EXPECT_THROW(strait.at(-0.1), InternalError);
  EXPECT_THROW(strait.at(std::nan("")), InternalError);
  EXPECT_THROW(strait.at(HUGE_VAL), InternalError);
  // Nothing left: the user's error, named, at any distance.
  EXPECT_THROW(strait.at(5.1), InvalidInputError);
  EXPECT_THROW(strait.at(1e6), InvalidInputError);
  EXPECT_THROW(strait.at(1e300), InvalidInputError);
}

}  // namespace
}  // namespace kinematic_coverage::core
