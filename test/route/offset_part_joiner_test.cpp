#include "polygon_coverage_ros_bridge/route/offset_part_joiner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"
#include "test/support/test_shapes.h"

namespace kinematic_coverage::core {
namespace {

constexpr double kWallDistance = 1.0;
/// A gap clearance that lets transits through the straits of the maps below.
constexpr double kAllowedGap = 0.5;
/// The joiner finds a gap's clearance to about 3 % of the wall distance, from below.
constexpr double kClearanceResolution = 0.04;

/// Three rooms in a row, 20, 14 and 10 m, joined by straits 1.5 m and 1.2 m wide: with a
/// 1 m wall distance the offset free area falls into three parts.
PolygonWithHoles threeRooms() {
  return {{{0, 0},    {20, 0},  {20, 9.25},  {22, 9.25},  {22, 3},  {36, 3},    {36, 9.4},
           {38, 9.4}, {38, 5},  {48, 5},     {48, 15},    {38, 15}, {38, 10.6}, {36, 10.6},
           {36, 17},  {22, 17}, {22, 10.75}, {20, 10.75}, {20, 20}, {0, 20}},
          {}};
}

/// Two 10 m squares joined by a strait 2 cm wide: 1 cm clearance, below the 2 cm (2 % of the
/// wall distance) that a transit keeps at least.
PolygonWithHoles twoSquaresJoinedByAHairline() {
  return {{{0, 0},
           {10, 0},
           {10, 4.99},
           {12, 4.99},
           {12, 0},
           {22, 0},
           {22, 10},
           {12, 10},
           {12, 5.01},
           {10, 5.01},
           {10, 10},
           {0, 10}},
          {}};
}

/// The hairline map (or a redrawing of it) joined from part 1: part 0 sealed with no
/// passage (a pinch point), no gap, the route area part 1 alone.
void expectTheHairlineSeals(const PolygonWithHoles& free_area) {
  const std::vector<PolygonWithHoles> parts = computeOffsetFreeArea(free_area, kWallDistance).parts;
  ASSERT_EQ(parts.size(), 2u);
  const JoinedOffsetArea joined =
      OffsetPartJoiner(free_area, kWallDistance, kAllowedGap).join(parts, 1);
  EXPECT_EQ(joined.joined_parts, std::vector<std::size_t>{1});
  ASSERT_EQ(joined.sealed_parts.size(), 1u);
  EXPECT_EQ(joined.sealed_parts.front().part, 0u);
  EXPECT_FALSE(joined.sealed_parts.front().widest_passage.has_value());
  EXPECT_TRUE(joined.gaps.empty());
  EXPECT_NEAR(area(joined.route_area), area(parts[1]), 1e-9);
}

/// Every point of the path at least `clearance` from the free area's boundary, every leg
/// inside it.
void expectPathInside(const PolygonWithHoles& free_area, const std::vector<Point2>& path,
                      double clearance) {
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    EXPECT_TRUE(segmentInside(free_area, path[i], path[i + 1]));
    for (int k = 0; k <= 20; ++k) {
      const Point2 p = path[i] + (path[i + 1] - path[i]) * (k / 20.0);
      EXPECT_GE(distanceToBoundary(p, free_area), clearance - 1e-9);
    }
  }
}

/// `area` with every edge cut into `pieces` collinear pieces: the same area, with as many
/// vertices as a chart (the joiner works in windows beyond 2 000).
PolygonWithHoles subdivided(const PolygonWithHoles& area, int pieces) {
  auto ring = [pieces](const Ring& given) {
    Ring result;
    for (std::size_t i = 0; i < given.size(); ++i) {
      const Point2& a = given[i];
      const Point2& b = given[(i + 1) % given.size()];
      for (int k = 0; k < pieces; ++k) result.push_back(a + (b - a) * (k / double(pieces)));
    }
    return result;
  };
  PolygonWithHoles result{ring(area.hull), {}};
  for (const Ring& hole : area.holes) result.holes.push_back(ring(hole));
  return result;
}

TEST(OffsetPartJoiner, JoinsThreeRoomsThroughTheirStraitsWithTheMostClearance) {
  const PolygonWithHoles free_area = threeRooms();
  const std::vector<PolygonWithHoles> parts = computeOffsetFreeArea(free_area, kWallDistance).parts;
  ASSERT_EQ(parts.size(), 3u);
  const JoinedOffsetArea joined =
      OffsetPartJoiner(free_area, kWallDistance, kAllowedGap).join(parts, 0);
  EXPECT_EQ(joined.joined_parts.size(), 3u);
  EXPECT_TRUE(joined.sealed_parts.empty());
  ASSERT_EQ(joined.gaps.size(), 2u);
  // The straits allow 0.75 m and 0.6 m (half their widths); the transits keep that.
  std::vector<double> clearances;
  for (const OffsetGap& gap : joined.gaps) {
    clearances.push_back(gap.clearance_m);
    expectPathInside(free_area, gap.path, gap.clearance_m);
    EXPECT_NEAR(distanceToBoundary(gap.narrowest_point, free_area), gap.clearance_m, 1e-9);
  }
  std::sort(clearances.begin(), clearances.end());
  EXPECT_LE(clearances[0], 0.6 + 1e-9);
  EXPECT_GE(clearances[0], 0.6 - kClearanceResolution);
  EXPECT_LE(clearances[1], 0.75 + 1e-9);
  EXPECT_GE(clearances[1], 0.75 - kClearanceResolution);
  // One area holds every part and the corridors (each at most its path's length plus a
  // half-width at both ends, times its width), inside the free area.
  double corridors = 0.0;
  for (const OffsetGap& gap : joined.gaps) {
    const double half_width = 0.1 * gap.clearance_m;
    for (std::size_t i = 0; i + 1 < gap.path.size(); ++i) {
      corridors += ((gap.path[i + 1] - gap.path[i]).norm() + 2.0 * half_width) * 2.0 * half_width;
    }
  }
  const double united = area(joined.route_area);
  EXPECT_GT(united, area(parts));
  EXPECT_LE(united, area(parts) + corridors);
  for (const PolygonWithHoles& part : parts) {
    for (const Point2& p : part.hull) EXPECT_TRUE(contains(joined.route_area, p, 1e-7));
  }
  for (const Point2& p : joined.route_area.hull) EXPECT_TRUE(contains(free_area, p));
}

TEST(OffsetPartJoiner, AnchorChoosesTheGroupButEveryReachablePartIsJoined) {
  const PolygonWithHoles free_area = threeRooms();
  const std::vector<PolygonWithHoles> parts = computeOffsetFreeArea(free_area, kWallDistance).parts;
  ASSERT_EQ(parts.size(), 3u);
  for (std::size_t anchor = 0; anchor < parts.size(); ++anchor) {
    const JoinedOffsetArea joined =
        OffsetPartJoiner(free_area, kWallDistance, kAllowedGap).join(parts, anchor);
    EXPECT_EQ(joined.joined_parts.size(), 3u) << "anchor " << anchor;
    EXPECT_EQ(joined.gaps.size(), 2u) << "anchor " << anchor;
  }
}

TEST(OffsetPartJoiner, AStraitNoRobotPassesSealsThePartBeyondIt) {
  // Two squares joined by a strait 2 cm wide: 1 cm clearance, below the 2 cm (2 % of the
  // wall distance) that a transit keeps at least.
  expectTheHairlineSeals(twoSquaresJoinedByAHairline());
}

TEST(OffsetPartJoiner, OnePartIsItsOwnRouteArea) {
  const PolygonWithHoles free_area = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {}};
  const std::vector<PolygonWithHoles> parts = computeOffsetFreeArea(free_area, kWallDistance).parts;
  const JoinedOffsetArea joined =
      OffsetPartJoiner(free_area, kWallDistance, kAllowedGap).join(parts, 0);
  EXPECT_EQ(joined.joined_parts, std::vector<std::size_t>{0});
  EXPECT_TRUE(joined.gaps.empty());
  EXPECT_NEAR(area(joined.route_area), 64.0, 1e-9);
}

TEST(OffsetPartJoiner, AnIslandCloseToTheShoreCutsOffAPocket) {
  // A square lake with a U-shaped island near the right shore: the strip between the
  // island's arms and the shore is 1.6 m wide, so its pocket is a part of its own.
  const PolygonWithHoles free_area = {
      {{0, 0}, {30, 0}, {30, 30}, {0, 30}},
      {{{20, 8}, {20, 22}, {28.4, 22}, {28.4, 20}, {22, 20}, {22, 10}, {28.4, 10}, {28.4, 8}}}};
  const std::vector<PolygonWithHoles> parts = computeOffsetFreeArea(free_area, kWallDistance).parts;
  ASSERT_EQ(parts.size(), 2u);
  const JoinedOffsetArea joined =
      OffsetPartJoiner(free_area, kWallDistance, kAllowedGap).join(parts, 0);
  EXPECT_EQ(joined.joined_parts.size(), 2u);
  ASSERT_EQ(joined.gaps.size(), 1u);
  EXPECT_LE(joined.gaps.front().clearance_m, 0.8 + 1e-9);
  EXPECT_GE(joined.gaps.front().clearance_m, 0.8 - kClearanceResolution);
  expectPathInside(free_area, joined.gaps.front().path, joined.gaps.front().clearance_m);
}

/// By default (the gap clearance the wall distance) no strait of the three rooms is passed:
/// each room beyond one is sealed, named with the bottleneck of its widest passage.
TEST(OffsetPartJoiner, GapsNarrowerThanTheGapClearanceSealThePartsBeyond) {
  const PolygonWithHoles free_area = threeRooms();
  const std::vector<PolygonWithHoles> parts = computeOffsetFreeArea(free_area, kWallDistance).parts;
  ASSERT_EQ(parts.size(), 3u);
  // Parts largest first: the 20 m room, the 14 m room beyond the 1.5 m strait, the 10 m
  // room beyond the 1.2 m strait.
  const JoinedOffsetArea sealed =
      OffsetPartJoiner(free_area, kWallDistance, kWallDistance).join(parts, 0);
  EXPECT_EQ(sealed.joined_parts, std::vector<std::size_t>{0});
  EXPECT_TRUE(sealed.gaps.empty());
  EXPECT_NEAR(area(sealed.route_area), area(parts[0]), 1e-9);
  ASSERT_EQ(sealed.sealed_parts.size(), 2u);
  const double expected[] = {0.75, 0.6};
  for (std::size_t i = 0; i < 2; ++i) {
    const SealedPart& part = sealed.sealed_parts[i];
    EXPECT_EQ(part.part, i + 1);
    ASSERT_TRUE(part.widest_passage.has_value());
    EXPECT_LE(part.widest_passage->clearance_m, expected[i] + 1e-9);
    EXPECT_GE(part.widest_passage->clearance_m, expected[i] - kClearanceResolution);
    expectPathInside(free_area, part.widest_passage->path, part.widest_passage->clearance_m);
  }
  // A gap clearance between the straits' clearances passes the wider one only.
  const JoinedOffsetArea between = OffsetPartJoiner(free_area, kWallDistance, 0.7).join(parts, 0);
  EXPECT_EQ(between.joined_parts, (std::vector<std::size_t>{0, 1}));
  ASSERT_EQ(between.gaps.size(), 1u);
  EXPECT_GE(between.gaps.front().clearance_m, 0.7 - kClearanceTolerance);
  ASSERT_EQ(between.sealed_parts.size(), 1u);
  EXPECT_EQ(between.sealed_parts.front().part, 2u);
}

/// A strait exactly two wall distances wide splits the mitred offset into two parts, but a
/// robot keeping the wall distance passes it along its middle: joined by default.
TEST(OffsetPartJoiner, AStraitOfTwiceTheWallDistanceIsPassedByDefault) {
  const PolygonWithHoles free_area = testing::twoRoomsJoinedByATwoMetreStrait();
  const std::vector<PolygonWithHoles> parts = computeOffsetFreeArea(free_area, kWallDistance).parts;
  ASSERT_EQ(parts.size(), 2u);
  const JoinedOffsetArea joined =
      OffsetPartJoiner(free_area, kWallDistance, kWallDistance).join(parts, 0);
  EXPECT_EQ(joined.joined_parts.size(), 2u);
  EXPECT_TRUE(joined.sealed_parts.empty());
  ASSERT_EQ(joined.gaps.size(), 1u);
  EXPECT_TRUE(keepsClearance(joined.gaps.front().clearance_m, kWallDistance));
}

/// The three rooms drawn with 2 020 vertices: joined in windows around the two smaller
/// rooms, through the same straits with the same clearances and corridors as the
/// 20-vertex drawing joined on the whole area.
TEST(OffsetPartJoiner, AChartSizedAreaIsJoinedInWindowsAsOnTheWholeArea) {
  const PolygonWithHoles coarse = threeRooms();
  const PolygonWithHoles fine = subdivided(coarse, 101);
  ASSERT_GT(fine.hull.size(), 2000u);
  const std::vector<PolygonWithHoles> parts = computeOffsetFreeArea(fine, kWallDistance).parts;
  ASSERT_EQ(parts.size(), 3u);
  const JoinedOffsetArea windowed =
      OffsetPartJoiner(fine, kWallDistance, kAllowedGap).join(parts, 0);
  const JoinedOffsetArea whole =
      OffsetPartJoiner(coarse, kWallDistance, kAllowedGap).join(parts, 0);
  EXPECT_EQ(windowed.joined_parts.size(), 3u);
  EXPECT_TRUE(windowed.sealed_parts.empty());
  ASSERT_EQ(windowed.gaps.size(), 2u);
  ASSERT_EQ(whole.gaps.size(), 2u);
  auto byClearance = [](std::vector<OffsetGap> gaps) {
    std::sort(gaps.begin(), gaps.end(),
              [](const OffsetGap& a, const OffsetGap& b) { return a.clearance_m < b.clearance_m; });
    return gaps;
  };
  const std::vector<OffsetGap> a = byClearance(windowed.gaps);
  const std::vector<OffsetGap> b = byClearance(whole.gaps);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(a[i].clearance_m, b[i].clearance_m, 1e-9);
    EXPECT_EQ(std::minmax(a[i].from_part, a[i].to_part), std::minmax(b[i].from_part, b[i].to_part));
    expectPathInside(fine, a[i].path, a[i].clearance_m);
  }
  EXPECT_NEAR(area(windowed.route_area), area(whole.route_area), 1e-6);
}

/// A part that no window joins (the strait seals it) is judged on the whole area: sealed.
TEST(OffsetPartJoiner, AChartSizedAreaSealsWhatNoStraitJoins) {
  const PolygonWithHoles free_area = subdivided(twoSquaresJoinedByAHairline(), 170);
  ASSERT_GT(free_area.hull.size(), 2000u);
  expectTheHairlineSeals(free_area);
}

}  // namespace
}  // namespace kinematic_coverage::core
