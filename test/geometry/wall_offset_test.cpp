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
#include "polygon_coverage_ros_bridge/geometry/region_intersection.h"
#include "polygon_coverage_ros_bridge/validation/polygon_cleaner.h"
#include "test/route/route_test_maps.h"
#include "test/support/hard_map_generator.h"
#include "test/support/random_polygons.h"
#include "test/support/test_shapes.h"

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

/// The hull and the holes of `part`.
std::vector<const Ring*> ringsOf(const PolygonWithHoles& part) {
  std::vector<const Ring*> rings = {&part.hull};
  for (const Ring& hole : part.holes) rings.push_back(&hole);
  return rings;
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

/// True when the line through a-b lies at `distance` from a wall vertex where the wall turns
/// toward the free area's side, on the far side from it: the cut of a squared-off mitre.
bool tangentToAWallCornerAt(const PolygonWithHoles& free_area, const Point2& a, const Point2& b,
                            double distance, double tolerance) {
  const Point2 u = (b - a).normalized();
  const Point2 normal(-u.y(), u.x());
  for (const Ring* ring : ringsOf(free_area)) {
    for (const Point2& corner : *ring) {
      if (std::abs(std::abs(normal.dot(corner - a)) - distance) <= tolerance) return true;
    }
  }
  return false;
}

/// On 40 random maps of 100 m with up to 8 holes, at three distances: the offset lies in the
/// free area at least the wall distance from every wall (no leg enters the wall band), each
/// of its edges runs parallel to a wall edge at exactly the wall distance (with the largest
/// mitre limit, the straight-skeleton offset: nothing of the free area is given up but the
/// mitres' corners) or, with the least limit, is a squared-off mitre's cut tangent to the
/// circle of the distance around a wall corner; its area shrinks as the distance grows, and
/// the squared-off corners keep more of it than the long mitres, but never more than the
/// exact (round) offset.
TEST(WallOffset, OffsetsKeepTheWallDistanceAndRunParallelToTheWalls) {
  std::mt19937 rng(29);
  constexpr double kTolerance = 1e-7;
  std::size_t edges_checked = 0;
  std::size_t cuts_checked = 0;
  for (int m = 0; m < 40; ++m) {
    SCOPED_TRACE("map " + std::to_string(m));
    const PolygonWithHoles map = testing::randomMap(rng, 100.0, 8, 1.0);
    const WallOffset offset(map, kMaxMiterLimit);
    const WallOffset squared(map, kMinMiterLimit);
    for (double distance : {0.3, 1.0, 2.5}) {
      const OffsetFreeArea result = squared.at(distance);
      EXPECT_GE(area(result.parts), area(offset.at(distance).parts) - 1e-9);
      EXPECT_LE(area(result.parts), area(squared.at(distance, OffsetCorners::kRound).parts) + 1e-9);
      for (const PolygonWithHoles& part : result.parts) {
        for (const Ring* ring : ringsOf(part)) {
          for (std::size_t i = 0, n = ring->size(); i < n; ++i) {
            const Point2& a = (*ring)[i];
            const Point2& b = (*ring)[(i + 1) % n];
            ASSERT_GE(wallDistance(map, a), distance - kTolerance);
            ASSERT_GE(wallDistance(map, 0.5 * (a + b)), distance - kTolerance);
            if ((b - a).norm() > 1e-6 && !parallelToAWallAt(map, a, b, distance, kTolerance)) {
              ASSERT_TRUE(tangentToAWallCornerAt(map, a, b, distance, 1e-6))
                  << "edge " << a.transpose() << " - " << b.transpose();
              ++cuts_checked;
            }
          }
        }
      }
    }
    double previous_area = area(map);
    for (double distance : {0.3, 1.0, 2.5}) {
      const OffsetFreeArea result = offset.at(distance);
      ASSERT_FALSE(result.parts.empty());
      const double offset_area = area(result.parts);
      EXPECT_LT(offset_area, previous_area);
      previous_area = offset_area;
      for (const PolygonWithHoles& part : result.parts) {
        for (const Ring* ring : ringsOf(part)) {
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
  EXPECT_GT(cuts_checked, 100u);
}

/// A needle of a hole 10 degrees sharp, 8 m long, pointing across a 40 m square: unlimited,
/// its grown outline's mitre reaches 1 / sin(5 degrees) = 11.5 wall distances beyond the
/// tip, out into the water; squared off, its cut lies one wall distance beyond the tip.
/// Mitre limits outside [2, 1000] are the caller's error.
TEST(WallOffset, ANeedlesMitreIsSquaredOffAtTheWallDistance) {
  const double half = 8.0 * std::tan(5.0 * M_PI / 180.0);
  const PolygonWithHoles lake = {{{0, 0}, {40, 0}, {40, 40}, {0, 40}},
                                 {{{8, 20 + half}, {16, 20}, {8, 20 - half}}}};
  const OffsetFreeArea long_mitre = computeOffsetFreeArea(lake, 1.5, kMaxMiterLimit);
  const OffsetFreeArea squared = computeOffsetFreeArea(lake, 1.5);
  ASSERT_EQ(long_mitre.parts.size(), 1u);
  ASSERT_EQ(squared.parts.size(), 1u);
  // The long mitre reaches x = 16 + 1.5 / sin(5 degrees) = 33.2; the cut, x = 17.5.
  double long_reach = 0.0;
  double squared_reach = 0.0;
  for (const Ring& hole : long_mitre.parts.front().holes) {
    for (const Point2& p : hole) long_reach = std::max(long_reach, p.x());
  }
  for (const Ring& hole : squared.parts.front().holes) {
    for (const Point2& p : hole) squared_reach = std::max(squared_reach, p.x());
  }
  EXPECT_NEAR(long_reach, 16.0 + 1.5 / std::sin(5.0 * M_PI / 180.0), 1e-6);
  EXPECT_NEAR(squared_reach, 17.5, 1e-6);
  EXPECT_GT(area(squared.parts), area(long_mitre.parts));
  EXPECT_THROW(WallOffset(lake, 1.9), InternalError);
  EXPECT_THROW(WallOffset(lake, 1001.0), InternalError);
  EXPECT_THROW(WallOffset(lake, std::nan("")), InternalError);
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

/// The exact offset (round corners): an L-shaped room keeps (1 - pi/4) m^2 more at its reflex
/// corner than the mitred one, and a 2 m square hole grows into a rounded square, each
/// within the chords' sag of the arcs. kRoundClear keeps the distance everywhere and falls
/// short of the exact area by at most its tolerance along the boundary.
TEST(WallOffset, RoundCornersAreTheExactOffset) {
  const PolygonWithHoles room = {{{0, 0}, {10, 0}, {10, 5}, {5, 5}, {5, 10}, {0, 10}}, {}};
  const double exact_room = 39.0 + (1.0 - M_PI / 4.0);
  const double room_area = area(WallOffset(room).at(1.0, OffsetCorners::kRound).parts);
  EXPECT_NEAR(room_area, exact_room, kExactOffsetArcTolerance * M_PI / 2.0);
  const std::vector<PolygonWithHoles> clear =
      WallOffset(room).at(1.0, OffsetCorners::kRoundClear).parts;
  EXPECT_LE(area(clear), exact_room);
  double perimeter = 0.0;
  const Ring& ring = clear.front().hull;
  for (std::size_t i = 0; i < ring.size(); ++i)
    perimeter += (ring[(i + 1) % ring.size()] - ring[i]).norm();
  EXPECT_GE(area(clear), exact_room - perimeter * kRoundClearArcTolerance);
  for (const Point2& p : clear.front().hull) EXPECT_GE(distanceToBoundary(p, room), 1.0 - 1e-9);
  const PolygonWithHoles lake = {{{0, 0}, {20, 0}, {20, 20}, {0, 20}},
                                 {{{9, 9}, {11, 9}, {11, 11}, {9, 11}}}};
  const double lake_area = area(WallOffset(lake).at(1.0, OffsetCorners::kRound).parts);
  EXPECT_NEAR(lake_area, 18.0 * 18.0 - (16.0 - 4.0 + M_PI), 1e-2);
}

/// True when two edges of `ring` that do not share a vertex cross each other.
bool crossesItself(const Ring& ring) {
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j + 1 == n) continue;
      const Point2& a = ring[i];
      const Point2& b = ring[(i + 1) % n];
      const Point2& c = ring[j];
      const Point2& d = ring[(j + 1) % n];
      if (cross(a, b, c) * cross(a, b, d) < 0.0 && cross(c, d, a) * cross(c, d, b) < 0.0) {
        return true;
      }
    }
  }
  return false;
}

/// A star of `spikes` points between radii 50 m and 30 m: sharp reflex corners between them.
Ring star(int spikes) {
  Ring ring;
  for (int i = 0; i < 2 * spikes; ++i) {
    const double a = M_PI * i / spikes;
    const double r = i % 2 == 0 ? 50.0 : 30.0;
    ring.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return ring;
}

/// Tangent corners lie between the mitred offset and the exact one: on 40 random maps and a
/// star with holes at three distances, every point of their rings (vertices and nine points
/// along each edge) keeps the wall distance within kClearanceTolerance, no ring crosses
/// itself, and their area lies between the mitred and the round offset's. At the L-shaped
/// room's right-angled reflex corner three tangents give up 3 tan(15 deg) - pi/4 m^2 to the
/// arc, where the mitre gives up 1 - pi/4.
TEST(WallOffset, TangentCornersLieBetweenTheMitredAndTheExactOffset) {
  const PolygonWithHoles room = {{{0, 0}, {10, 0}, {10, 5}, {5, 5}, {5, 10}, {0, 10}}, {}};
  const OffsetFreeArea tangent_room = WallOffset(room).at(1.0, OffsetCorners::kTangent);
  ASSERT_EQ(tangent_room.parts.size(), 1u);
  EXPECT_NEAR(area(tangent_room.parts), 39.0 + 1.0 - 3.0 * std::tan(M_PI / 12.0), 1e-9);
  EXPECT_EQ(tangent_room.parts.front().hull.size(), 8u);

  std::mt19937 rng(31);
  std::vector<PolygonWithHoles> maps;
  for (int m = 0; m < 40; ++m) maps.push_back(testing::randomMap(rng, 100.0, 8, 1.0));
  maps.push_back({star(24), {{{-3, -3}, {3, -3}, {0, 3}}, {{10, 0}, {14, 0}, {14, 1}, {10, 1}}}});
  std::size_t points_checked = 0;
  for (std::size_t m = 0; m < maps.size(); ++m) {
    SCOPED_TRACE("map " + std::to_string(m));
    const PolygonWithHoles& map = maps[m];
    const WallOffset offset(map);
    for (double distance : {0.3, 1.0, 2.5}) {
      const OffsetFreeArea tangent = offset.at(distance, OffsetCorners::kTangent);
      const double mitred_area = area(offset.at(distance).parts);
      const double round_area = area(offset.at(distance, OffsetCorners::kRound).parts);
      EXPECT_GE(area(tangent.parts), mitred_area - 1e-9);
      EXPECT_LE(area(tangent.parts), round_area + 1e-9);
      for (const PolygonWithHoles& part : tangent.parts) {
        for (const Ring* ring : ringsOf(part)) {
          ASSERT_FALSE(crossesItself(*ring));
          for (std::size_t i = 0, n = ring->size(); i < n; ++i) {
            const Point2& a = (*ring)[i];
            const Point2& b = (*ring)[(i + 1) % n];
            ASSERT_TRUE(contains(map, a));
            for (int k = 0; k < 10; ++k) {
              const Point2 p = a + (k / 10.0) * (b - a);
              ASSERT_GE(wallDistance(map, p), distance - kClearanceTolerance)
                  << p.transpose() << " on edge " << a.transpose() << " - " << b.transpose();
              ++points_checked;
            }
          }
        }
      }
    }
  }
  EXPECT_GT(points_checked, 25000u);
}

/// The same on ten maps of each hard family at their own wall distance, cleaned as the
/// planner cleans them: shorelines' sharp bays left rings that crossed themselves where the
/// caps shared the mitred offset's edges.
TEST(WallOffset, TangentCornersOnTheHardFamiliesKeepTheWallDistance) {
  for (const testing::MapFamily family :
       {testing::MapFamily::kComb, testing::MapFamily::kSpiral, testing::MapFamily::kRooms,
        testing::MapFamily::kShoreline, testing::MapFamily::kTouchingHoles,
        testing::MapFamily::kStar}) {
    const testing::HardMapGenerator generator(family);
    for (std::uint64_t seed = 0; seed < 10; ++seed) {
      const testing::HardMap map = generator.generate(seed);
      SCOPED_TRACE(testing::HardMapGenerator::name(family) + " seed " + std::to_string(seed));
      const PolygonWithHoles free_area = PolygonCleaner().clean(map.mission.polygon).free_area;
      const double distance = map.mission.parameters.wall_distance;
      const WallOffset offset(free_area);
      const OffsetFreeArea tangent = offset.at(distance, OffsetCorners::kTangent);
      EXPECT_GE(area(tangent.parts), area(offset.at(distance).parts) - 1e-9);
      EXPECT_LE(area(tangent.parts), area(offset.at(distance, OffsetCorners::kRound).parts) + 1e-9);
      for (const PolygonWithHoles& part : tangent.parts) {
        for (const Ring* ring : ringsOf(part)) {
          ASSERT_FALSE(crossesItself(*ring));
          for (std::size_t i = 0, n = ring->size(); i < n; ++i) {
            const Point2 middle = 0.5 * ((*ring)[i] + (*ring)[(i + 1) % n]);
            ASSERT_GE(wallDistance(free_area, (*ring)[i]), distance - kClearanceTolerance);
            ASSERT_GE(wallDistance(free_area, middle), distance - kClearanceTolerance);
          }
        }
      }
    }
  }
}

/// Coverage is measured against the round parts that hold the planned ones: of two rooms
/// that a 2 m strait splits at 1.5 m, one planned room gives its own room, rounded; both
/// give both; wall distance 0 gives the parts themselves.
TEST(WallOffset, ExactOffsetPartsAreTheRoundPartsHoldingThePlannedOnes) {
  const PolygonWithHoles rooms = testing::twoRoomsJoinedByATwoMetreStrait();
  const std::vector<PolygonWithHoles> mitred = computeOffsetFreeArea(rooms, 1.5).parts;
  ASSERT_EQ(mitred.size(), 2u);
  const std::vector<PolygonWithHoles> round =
      WallOffset(rooms).at(1.5, OffsetCorners::kRound).parts;
  ASSERT_EQ(round.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const std::vector<PolygonWithHoles> exact = exactOffsetParts(rooms, 1.5, {mitred[k]});
    ASSERT_EQ(exact.size(), 1u);
    EXPECT_GT(area(exact), area(mitred[k]));
    EXPECT_TRUE(contains(exact.front(), mitred[k].hull.front(), 1e-9));
    EXPECT_NEAR(area(exact), area(round[k]), 1e-9);
  }
  EXPECT_NEAR(area(exactOffsetParts(rooms, 1.5, mitred)), area(round), 1e-9);
  const std::vector<PolygonWithHoles> itself = {rooms};
  EXPECT_EQ(exactOffsetParts(rooms, 0.0, itself).front().hull, rooms.hull);
}

/// The exact offset against its definition, on maps of touching holes (whose mitres close
/// pockets and necks that a robot keeping its distance reaches): of random points of the
/// free area (fixed seed), every one at least the wall distance plus the chords' sag from
/// the walls lies in the exact parts, and every one in them lies at least the wall distance
/// less that sag from the walls; the mitred parts miss some of the former.
TEST(WallOffset, ExactOffsetPartsHoldThePointsAtLeastTheWallDistanceFromTheWalls) {
  const testing::HardMapGenerator generator(testing::MapFamily::kTouchingHoles);
  std::mt19937 random(11);
  std::size_t missed_by_mitred = 0;
  for (const std::uint64_t seed : {2u, 3u, 4u}) {
    const testing::HardMap map = generator.generate(seed);
    const PolygonWithHoles free_area = PolygonCleaner().clean(map.mission.polygon).free_area;
    const double distance = map.mission.parameters.wall_distance;
    const std::vector<PolygonWithHoles> mitred = computeOffsetFreeArea(free_area, distance).parts;
    const std::vector<PolygonWithHoles> exact = exactOffsetParts(free_area, distance, mitred);
    const auto inside = [](const std::vector<PolygonWithHoles>& parts, const Point2& p) {
      return std::any_of(parts.begin(), parts.end(),
                         [&](const PolygonWithHoles& part) { return contains(part, p); });
    };
    Point2 low = free_area.hull.front();
    Point2 high = low;
    for (const Point2& p : free_area.hull) {
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
    std::uniform_real_distribution<double> x(low.x(), high.x());
    std::uniform_real_distribution<double> y(low.y(), high.y());
    for (int k = 0; k < 20000; ++k) {
      const Point2 p(x(random), y(random));
      if (!contains(free_area, p)) continue;
      const double clearance = wallDistance(free_area, p);
      if (clearance >= distance + kExactOffsetArcTolerance) {
        EXPECT_TRUE(inside(exact, p)) << "seed " << seed << " " << p.transpose();
        missed_by_mitred += inside(mitred, p) ? 0 : 1;
      }
      if (inside(exact, p)) {
        EXPECT_GE(clearance, distance - kExactOffsetArcTolerance) << "seed " << seed;
      }
    }
  }
  EXPECT_GT(missed_by_mitred, 0u);
}

/// The area of `parts`, and of the parts of `area` in [low, high] by the exact-kernel
/// intersection.
double totalArea(const std::vector<PolygonWithHoles>& parts) {
  double total = 0.0;
  for (const PolygonWithHoles& part : parts) total += area(part);
  return total;
}

// Clipping to a box with Clipper (after cutting the rings down to a slightly larger box)
// gives the exact-kernel intersection's parts: the same number and area, every vertex
// inside the box; on jagged stars whose spikes cross the box many times, maps of holes cut
// by it, boxes holding a whole hole, beyond the hull, and inside a hole.
TEST(ClipToBox, AgreesWithTheExactIntersection) {
  std::mt19937 rng(404);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int crossings = 0;
  for (int map_index = 0; map_index < 24; ++map_index) {
    const bool jagged = map_index % 2 == 1;
    const PolygonWithHoles map =
        jagged ? testing::jaggedStarMap(rng, 300, 40.0) : testing::randomMap(rng, 100.0, 12, 1.0);
    const double offset = jagged ? -100.0 : 0.0;  // the jagged map is centred at the origin
    for (int box_index = 0; box_index < 6; ++box_index) {
      const Point2 centre(offset - 20.0 + 140.0 * unit(rng), offset - 20.0 + 140.0 * unit(rng));
      const Point2 half(2.0 + 30.0 * unit(rng), 2.0 + 30.0 * unit(rng));
      const Point2 low = centre - half;
      const Point2 high = centre + half;
      const PolygonWithHoles box{{low, {high.x(), low.y()}, high, {low.x(), high.y()}}, {}};
      const std::vector<PolygonWithHoles> exact = intersectWithRegions(map, {box}, 0.0);
      const std::vector<PolygonWithHoles> clipped = clipToBox(map, low, high);
      SCOPED_TRACE("map " + std::to_string(map_index) + " box " + std::to_string(box_index));
      EXPECT_EQ(clipped.size(), exact.size());
      EXPECT_NEAR(totalArea(clipped), totalArea(exact), 1e-6 * (1.0 + totalArea(exact)));
      crossings += exact.size() > 1;
      for (const PolygonWithHoles& part : clipped) {
        EXPECT_GT(signedArea(part.hull), 0.0);
        for (const Point2& p : part.hull) {
          EXPECT_TRUE((p.array() >= low.array() - 1e-9).all() &&
                      (p.array() <= high.array() + 1e-9).all())
              << p.transpose();
        }
        for (const Ring& hole : part.holes) EXPECT_LT(signedArea(hole), 0.0);
      }
    }
  }
  EXPECT_GT(crossings, 5);  // boxes that the hull or the holes cut into several parts
  // Beyond the hull: nothing.
  const PolygonWithHoles square{{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                                {{{4, 4}, {4, 6}, {6, 6}, {6, 4}}}};
  EXPECT_TRUE(clipToBox(square, {20, 20}, {30, 30}).empty());
  // Inside the hole: nothing; around it: the ring between.
  EXPECT_TRUE(clipToBox(square, {4.5, 4.5}, {5.5, 5.5}).empty());
  const std::vector<PolygonWithHoles> around = clipToBox(square, {3, 3}, {7, 7});
  ASSERT_EQ(around.size(), 1u);
  EXPECT_EQ(around[0].holes.size(), 1u);
  EXPECT_NEAR(area(around[0]), 16.0 - 4.0, 1e-9);
}

}  // namespace
}  // namespace kinematic_coverage::core
