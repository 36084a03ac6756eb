#include "polygon_coverage_ros_bridge/repair/exact_offset_excursions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"
#include "test/support/sampled_wall_distance.h"

namespace kinematic_coverage::core {
namespace {

/// A 40 m x 30 m room around an equilateral triangle of 6 m sides: each of its corners
/// bulges into the free area by 120 degrees, so that the mitre of the offset by 2 m lies
/// 4 m from the corner, 2 m beyond the round corner of the exact offset.
PolygonWithHoles roomAroundTriangle() {
  const double height = 3.0 * std::sqrt(3.0);
  return {{{0, 0}, {40, 0}, {40, 30}, {0, 30}}, {{{17, 13}, {20, 13 + height}, {23, 13}}}};
}

/// Every excursion from the corners of the offset's rings (insides to their left), the
/// mitres unlimited (a 120-degree corner's mitre is exactly at the default limit).
struct Excursion {
  Point2 corner;
  Point2 apex;
};
std::vector<Excursion> everyExcursion(const PolygonWithHoles& free_area, double wall_distance,
                                      const ExactOffsetExcursions& excursions) {
  std::vector<Excursion> result;
  for (const PolygonWithHoles& part :
       computeOffsetFreeArea(free_area, wall_distance, kMaxMiterLimit).parts) {
    std::vector<Ring> rings = {part.hull};
    rings.insert(rings.end(), part.holes.begin(), part.holes.end());
    for (const Ring& ring : rings) {
      const std::size_t n = ring.size();
      for (std::size_t i = 0; i < n; ++i) {
        if (const auto apex = excursions.apex(ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n])) {
          result.push_back({ring[i], *apex});
        }
      }
    }
  }
  return result;
}

// From each mitre of the grown triangle, the excursion runs 2 m toward the triangle's
// corner and ends on the round corner: 2 m from the wall, on the line to the corner.
TEST(ExactOffsetExcursions, AMitreLeadsOutToTheRoundCorner) {
  const PolygonWithHoles room = roomAroundTriangle();
  const ExactOffsetExcursions excursions(room, 2.0, 0.1, 10.0);
  const std::vector<Excursion> found = everyExcursion(room, 2.0, excursions);
  ASSERT_EQ(found.size(), 3u);
  for (const Excursion& excursion : found) {
    EXPECT_NEAR((excursion.apex - excursion.corner).norm(), 2.0, 1e-4);
    EXPECT_NEAR(distanceToBoundary(excursion.apex, room), 2.0, 1e-5);
    EXPECT_TRUE(keepsClearance(
        testing::sampledWallDistance(room, {excursion.corner, excursion.apex}), 2.0));
    // The apex lies on the way from the mitre to the triangle's nearest corner.
    const Point2 corner = excursion.corner + 2.0 * (excursion.apex - excursion.corner);
    EXPECT_NEAR(distanceToBoundary(corner, room), 0.0, 1e-5);
  }
}

// The room's own corners turn toward the offset's inside, and the sides run straight: no
// excursions there; with a wall distance of 0, none at all.
TEST(ExactOffsetExcursions, NoneWhereTheRingTurnsInwardOrRunsStraightOrTheOffsetIsExact) {
  const PolygonWithHoles room = roomAroundTriangle();
  const ExactOffsetExcursions excursions(room, 2.0, 0.1, 10.0);
  EXPECT_FALSE(excursions.apex({2, 28}, {2, 2}, {38, 2}));  // a room corner, inside to the left
  EXPECT_FALSE(excursions.apex({2, 2}, {20, 2}, {38, 2}));  // straight on
  EXPECT_FALSE(excursions.apex({2, 2}, {2, 2}, {38, 2}));   // a repeated vertex
  EXPECT_FALSE(excursions.apex({2, 2}, {20, 2}, {2, 2}));   // doubling back
  EXPECT_TRUE(everyExcursion(room, 2.0, ExactOffsetExcursions(room, 0.0, 0.1, 10.0)).empty());
  EXPECT_TRUE(everyExcursion(room, 2.0, ExactOffsetExcursions()).empty());
}

// Excursions shorter than the minimum are left out; longer ones are cut to the maximum.
TEST(ExactOffsetExcursions, LengthsStayBetweenTheMinimumAndTheMaximum) {
  const PolygonWithHoles room = roomAroundTriangle();
  EXPECT_TRUE(everyExcursion(room, 2.0, ExactOffsetExcursions(room, 2.0, 2.5, 10.0)).empty());
  for (const Excursion& excursion :
       everyExcursion(room, 2.0, ExactOffsetExcursions(room, 2.0, 0.1, 0.5))) {
    EXPECT_NEAR((excursion.apex - excursion.corner).norm(), 0.5, 1e-9);
  }
}

// A slot 1.6 m wide opens from a room's top wall at y = 10 (wall distance 1 m): the mitred
// offset runs straight past its mouth at y = 9, while the points 1 m from its corners reach
// up to y = 10 - 0.6. The excursion up from below the mouth's middle ends there.
TEST(ExactOffsetExcursions, TowardASlotsMouthEndsWhereItsCornersAreTheWallDistanceAway) {
  const PolygonWithHoles room{
      {{0, 0}, {20, 0}, {20, 10}, {10.8, 10}, {10.8, 15}, {9.2, 15}, {9.2, 10}, {0, 10}}, {}};
  const ExactOffsetExcursions excursions(room, 1.0, 0.05, 5.0);
  const std::optional<Point2> apex = excursions.toward({10, 9}, {0, 1});
  ASSERT_TRUE(apex);
  EXPECT_NEAR(apex->x(), 10.0, 1e-12);
  EXPECT_NEAR(apex->y(), 9.4, 1e-3);
  EXPECT_GE(distanceToBoundary(*apex, room), 1.0 - 1e-9);
  // Beside the mouth the wall is the wall distance away already; a zero direction is none.
  EXPECT_FALSE(excursions.toward({5, 9}, {0, 1}));
  EXPECT_FALSE(excursions.toward({10, 9}, {0, 0}));
}

/// A 20 m x 10 m room with a slot 4 m wide up from its top (x 9 to 13) that bends right
/// into an arm 4 m wide (y 14 to 18): with a wall distance of 1 m the exact offset runs up
/// the slot and along the arm, round the slot's right wall.
PolygonWithHoles roomWithBentSlot() {
  return {{{0, 0},
           {20, 0},
           {20, 10},
           {13, 10},
           {13, 14},
           {20, 14},
           {20, 18},
           {9, 18},
           {9, 10},
           {0, 10}},
          {}};
}

// Toward a point of the arm, the straight excursion stops in the slot; the walk goes on
// up the slot and along the arm to within its reach of the point, every leg keeping the
// wall distance.
TEST(ExactOffsetExcursions, AWalkFollowsABentFunnel) {
  const PolygonWithHoles room = roomWithBentSlot();
  const ExactOffsetExcursions excursions(room, 1.0, 0.05, 5.0);
  const Point2 from(11, 9);
  const Point2 target(17, 16);
  const std::optional<Point2> straight = excursions.toward(from, target - from);
  ASSERT_TRUE(straight);
  EXPECT_GT((*straight - target).norm(), 5.0);
  const std::vector<Point2> way = excursions.walk(from, target, 0.5);
  ASSERT_GE(way.size(), 2u);
  EXPECT_EQ(way.front(), *straight);
  EXPECT_LE((way.back() - target).norm(), 0.5);
  Point2 previous = from;
  for (const Point2& end : way) {
    EXPECT_TRUE(excursions.keepsDistance(previous, end));
    EXPECT_GE(testing::sampledWallDistance(room, {previous, end}), 1.0 - 1e-3)
        << previous.transpose() << " -> " << end.transpose();
    previous = end;
  }
}

// Toward a point in a slot narrower than two wall distances no leg comes nearer after the
// excursion to the slot's mouth; with no way to start at all the walk is empty.
TEST(ExactOffsetExcursions, AWalkEndsWhereNoLegComesNearer) {
  const PolygonWithHoles room{
      {{0, 0}, {20, 0}, {20, 10}, {10.8, 10}, {10.8, 15}, {9.2, 15}, {9.2, 10}, {0, 10}}, {}};
  const ExactOffsetExcursions excursions(room, 1.0, 0.05, 5.0);
  const std::vector<Point2> way = excursions.walk({10, 9}, {10, 14}, 0.5);
  ASSERT_EQ(way.size(), 1u);
  EXPECT_NEAR(way.front().y(), 9.4, 1e-3);
  EXPECT_TRUE(ExactOffsetExcursions().walk({10, 9}, {10, 14}, 0.5).empty());
}

// Random segments in the room with the slot (fixed seed): keepsDistance agrees with the
// distance to the walls sampled a centimetre apart wherever that is clear of the wall
// distance by more than the sampling can miss (half a centimetre); a segment into the slot
// never keeps it.
TEST(ExactOffsetExcursions, KeepsDistanceAgreesWithTheDistanceToTheWalls) {
  constexpr double kSampling = 0.006;
  const PolygonWithHoles room{
      {{0, 0}, {20, 0}, {20, 10}, {10.8, 10}, {10.8, 15}, {9.2, 15}, {9.2, 10}, {0, 10}}, {}};
  const ExactOffsetExcursions excursions(room, 1.0, 0.05, 5.0);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> x(5.0, 15.0);
  std::uniform_real_distribution<double> y(6.0, 12.0);
  int kept = 0;
  int refused = 0;
  for (int k = 0; k < 2000; ++k) {
    const Point2 a(x(random), y(random));
    const Point2 b(x(random), y(random));
    if (!contains(room, a) || !contains(room, b)) continue;
    const double distance = testing::sampledWallDistance(room, {a, b});
    if (distance > 1.0 + kSampling) {
      EXPECT_TRUE(excursions.keepsDistance(a, b)) << a.transpose() << " " << b.transpose();
      ++kept;
    } else if (distance < 1.0 - kSampling) {
      EXPECT_FALSE(excursions.keepsDistance(a, b)) << a.transpose() << " " << b.transpose();
      ++refused;
    }
  }
  EXPECT_GT(kept, 20);
  EXPECT_GT(refused, 200);
  EXPECT_FALSE(excursions.keepsDistance({10, 9}, {10, 14}));  // into the slot
  EXPECT_TRUE(excursions.keepsDistance({2, 2}, {18, 8}));
  EXPECT_TRUE(ExactOffsetExcursions().keepsDistance({10, 9}, {10, 14}));
}

// Random rooms of random convex holes (fixed seed): every excursion keeps the wall distance
// along its whole length, and ends where the walls come that near (within the tracing's
// tolerance) unless it is cut at the maximum.
TEST(ExactOffsetExcursions, EveryExcursionOfRandomRoomsKeepsTheWallDistance) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int checked = 0;
  for (int map = 0; map < 20; ++map) {
    PolygonWithHoles room{{{0, 0}, {30, 0}, {30, 30}, {0, 30}}, {}};
    for (int h = 0; h < 4; ++h) {
      const Point2 centre(5.0 + 20.0 * unit(random), 5.0 + 20.0 * unit(random));
      std::vector<Point2> points;
      for (int k = 0; k < 5; ++k) {
        const double angle = 2.0 * M_PI * unit(random);
        points.push_back(centre +
                         (0.5 + 2.5 * unit(random)) * Point2(std::cos(angle), std::sin(angle)));
      }
      Ring hole = convexHull(points);
      if (hole.size() < 3) continue;
      bool apart = true;
      for (const Ring& other : room.holes) {
        for (const Point2& p : hole) apart = apart && !insideRing(p, other);
        for (const Point2& p : other) apart = apart && !insideRing(p, hole);
      }
      if (apart) room.holes.push_back(hole);
    }
    const double wall_distance = 0.5 + 1.5 * unit(random);
    const ExactOffsetExcursions excursions(room, wall_distance, 0.05, 3.0);
    std::vector<Excursion> found;
    try {
      found = everyExcursion(room, wall_distance, excursions);
    } catch (const std::exception&) {
      continue;  // holes that overlap: not a valid room
    }
    for (const Excursion& excursion : found) {
      ++checked;
      const double length = (excursion.apex - excursion.corner).norm();
      EXPECT_GE(length, 0.05);
      EXPECT_LE(length, 3.0 + 1e-9);
      EXPECT_TRUE(keepsClearance(
          testing::sampledWallDistance(room, {excursion.corner, excursion.apex}), wall_distance))
          << "map " << map << " corner " << excursion.corner.transpose();
      if (length < 3.0 - 1e-9) {
        EXPECT_NEAR(distanceToBoundary(excursion.apex, room), wall_distance, 1e-3);
      }
    }
  }
  EXPECT_GT(checked, 50);
}

}  // namespace
}  // namespace kinematic_coverage::core
