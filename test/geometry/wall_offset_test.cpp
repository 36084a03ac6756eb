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

TEST(WallOffset, RingsWhoseSkeletonWouldNotFitAreRefusedBeforeItIsBuilt) {
  // 6 000 vertices, 3 000 reflex: 18e6 vertex pairs, over 2 times the limit (the skeleton
  // would take about 900 MB); refused in milliseconds.
  const PolygonWithHoles noisy = {circle(6000, true), {}};
  try {
    computeOffsetFreeArea(noisy, 1.0);
    ADD_FAILURE() << "accepted";
  } catch (const InvalidInputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("the hull has 6000 vertices, 3000 of them reflex"), std::string::npos)
        << message;
    EXPECT_NE(message.find("18000000 pairs, 2.25 times the limit of 8000000"), std::string::npos)
        << message;
    EXPECT_NE(message.find("simplify the hull to fewer vertices"), std::string::npos) << message;
  }
  // The same ring as a hole is named by its index.
  PolygonWithHoles with_hole = {{{-500, -500}, {500, -500}, {500, 500}, {-500, 500}}, {}};
  with_hole.holes.push_back(circle(6000, true));
  std::reverse(with_hole.holes.back().begin(), with_hole.holes.back().end());
  EXPECT_THROW(
      {
        try {
          computeOffsetFreeArea(with_hole, 1.0);
        } catch (const InvalidInputError& error) {
          EXPECT_NE(std::string(error.what()).find("hole 0 has 6000 vertices"), std::string::npos)
              << error.what();
          throw;
        }
      },
      InvalidInputError);
  // Without a wall offset no skeleton is built, and nothing is refused.
  EXPECT_NO_THROW(computeOffsetFreeArea(noisy, 0.0));
}

TEST(WallOffset, ManyConvexVerticesAreNotLimited) {
  // 6 000 vertices, none reflex: the skeleton stays small, the offset is computed.
  const PolygonWithHoles round = {circle(6000, false), {}};
  const OffsetFreeArea offset = computeOffsetFreeArea(round, 1.0);
  EXPECT_NEAR(area(offset.parts), area(round) * std::pow(149.0 / 150.0, 2), 1.0);
}

void expectSameParts(const OffsetFreeArea& a, const OffsetFreeArea& b) {
  ASSERT_EQ(a.parts.size(), b.parts.size());
  for (std::size_t k = 0; k < a.parts.size(); ++k) {
    EXPECT_EQ(a.parts[k].hull, b.parts[k].hull) << "part " << k;
    EXPECT_EQ(a.parts[k].holes, b.parts[k].holes) << "part " << k;
  }
}

/// The part joiner offsets one area at many distances from skeletons built once up to the
/// wall distance: each offset is the one computed on its own, bit for bit, on random maps
/// and on a strait that splits the area below the largest distance.
TEST(WallOffset, SkeletonsBuiltOnceGiveEveryOffsetBitForBit) {
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
    const double largest = m < 2 ? 1.5 : 3.0;
    const WallOffset offset(maps[m], largest);
    for (double share : {1.0, 0.75, 0.5, 0.3, 0.02}) {
      expectSameParts(offset.at(share * largest), computeOffsetFreeArea(maps[m], share * largest));
    }
  }
  const WallOffset strait(maps[0], 1.5);
  EXPECT_EQ(strait.at(1.5).parts.size(), 2u);
  EXPECT_EQ(strait.at(0.4).parts.size(), 1u);
  EXPECT_THROW(strait.at(1.6), InternalError);
  EXPECT_THROW(strait.at(0.0), InternalError);
}

}  // namespace
}  // namespace kinematic_coverage::core
