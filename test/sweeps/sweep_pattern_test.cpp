#include "polygon_coverage_ros_bridge/sweeps/sweep_pattern.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "polygon_coverage_ros_bridge/decomposition/best_decomposition.h"
#include "polygon_coverage_ros_bridge/decomposition/sweep_direction.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "test/support/random_polygons.h"

namespace kinematic_coverage::core {
namespace {

std::vector<Point2> straight(const Point2& a, const Point2& b) { return {a, b}; }

/// How far (relative to the coordinates' scale) a lane end may lie outside its cell.
constexpr double kEndRounding = 1e-13;

/// Lanes lie in the cell, run parallel to the direction, and neighbouring lanes are at
/// most one sweep distance apart.
void expectValidLanes(const Ring& cell, double direction, const FrustumSensor& sensor) {
  const auto lanes = SweepPatternGenerator(sensor).lanes(cell, direction);
  ASSERT_FALSE(lanes.empty());
  const PolygonWithHoles area{cell, {}};
  const Point2 along = directionVector(direction);
  const Point2 across(along.y(), -along.x());  // the order of the lanes
  double scale = 1.0;
  for (const Point2& p : cell) scale = std::max(scale, p.cwiseAbs().maxCoeff());
  for (std::size_t k = 0; k < lanes.size(); ++k) {
    const auto& [a, b] = lanes[k];
    EXPECT_TRUE(segmentInside(area, a, b, 1e-7));
    // Lane ends are route points: inside the cell up to rounding, not up to a tolerance.
    EXPECT_TRUE(contains(area, a, kEndRounding * scale)) << "end " << a.transpose();
    EXPECT_TRUE(contains(area, b, kEndRounding * scale)) << "end " << b.transpose();
    // Parallel up to the corner tolerance (1e-9 of the scale) that an end through an
    // acute corner may move by to stay inside the cell.
    EXPECT_NEAR(std::abs(cross({0, 0}, along, b - a)), 0.0, std::max(1e-7, 2e-9 * scale));
    EXPECT_GE((b - a).dot(along), -1e-9);
    if (k > 0) {
      const double gap = (a - lanes[k - 1].first).dot(across);
      EXPECT_GT(gap, 0.0);
      EXPECT_LE(gap, sensor.sweepDistance() + 1e-9);
    }
  }
  // Every corner lies in some lane's swept footprint.
  for (const Point2& corner : cell) {
    bool seen = false;
    for (const auto& [a, b] : lanes) {
      const double lateral = std::abs((corner - a).dot(across));
      const double onward = (corner - a).dot(along);
      seen = seen ||
             (lateral <= 0.5 * sensor.width() + 1e-7 && onward >= -0.5 * sensor.length() - 1e-7 &&
              onward <= (b - a).dot(along) + 0.5 * sensor.length() + 1e-7);
    }
    EXPECT_TRUE(seen) << "corner " << corner.transpose();
  }
}

/// Every point of the cell (a grid over it and points along its edges) lies in the
/// footprint swept along some lane: within W/2 across the lane and within L/2 beyond its
/// ends.
void expectCellSeen(const Ring& cell, double direction, const FrustumSensor& sensor,
                    const std::vector<std::pair<Point2, Point2>>& lanes) {
  const Point2 along = directionVector(direction);
  const Point2 across(along.y(), -along.x());
  auto seen = [&](const Point2& p) {
    for (const auto& [a, b] : lanes) {
      const double lateral = std::abs((p - a).dot(across));
      const double onward = (p - a).dot(along);
      if (lateral <= 0.5 * sensor.width() + 1e-7 && onward >= -0.5 * sensor.length() - 1e-7 &&
          onward <= (b - a).dot(along) + 0.5 * sensor.length() + 1e-7) {
        return true;
      }
    }
    return false;
  };
  std::vector<Point2> points;
  for (std::size_t i = 0; i < cell.size(); ++i) {
    const Point2& a = cell[i];
    const Point2& b = cell[(i + 1) % cell.size()];
    for (int k = 0; k < 200; ++k) points.push_back(a + (b - a) * (k / 200.0));
  }
  Point2 lo = cell.front();
  Point2 hi = cell.front();
  for (const Point2& p : cell) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  for (int i = 0; i <= 100; ++i) {
    for (int j = 0; j <= 100; ++j) {
      const Point2 p = lo + (hi - lo).cwiseProduct(Point2(i / 100.0, j / 100.0));
      if (insideRing(p, cell)) points.push_back(p);
    }
  }
  int unseen = 0;
  for (const Point2& p : points) {
    if (!seen(p) && ++unseen <= 3) ADD_FAILURE() << "unseen point " << p.transpose();
  }
  EXPECT_EQ(unseen, 0) << "of " << points.size() << " points";
}

TEST(SweepPattern, RectangleLaneCountAndMargins) {
  const Ring rectangle = {{0, 0}, {20, 0}, {20, 10}, {0, 10}};
  const FrustumSensor sensor(4.0, 1.0, 0.25);  // s = 3, margin = min(1.5, 2 - 0.5) = 1.5
  const auto lanes = SweepPatternGenerator(sensor).lanes(rectangle, 0.0);
  // Lanes along x stacked across y from 1.5 to 8.5: span 7 -> ceil(7 / 3) = 3 gaps.
  ASSERT_EQ(lanes.size(), 4u);
  EXPECT_NEAR(std::min(lanes.front().first.y(), lanes.back().first.y()), 1.5, 1e-9);
  EXPECT_NEAR(std::max(lanes.front().first.y(), lanes.back().first.y()), 8.5, 1e-9);
  for (const auto& lane : lanes) {
    EXPECT_NEAR(lane.first.x(), 0.0, 1e-9);
    EXPECT_NEAR(lane.second.x(), 20.0, 1e-9);
  }
  expectValidLanes(rectangle, 0.0, sensor);
}

TEST(SweepPattern, LanesJustOverOneLaneApartAreSpreadEvenly) {
  // Altitude 7.87 with s = 7.74 and margin 3.87: two lanes at the margins would be 0.13 m
  // apart; they are spread to a quarter and three quarters instead.
  const Ring band = {{0, 0}, {30, 0}, {30, 7.87}, {0, 7.87}};
  const FrustumSensor sensor(12.9, 1.6, 0.4);
  const auto lanes = SweepPatternGenerator(sensor).lanes(band, 0.0);
  ASSERT_EQ(lanes.size(), 2u);
  EXPECT_NEAR(std::abs(lanes[0].first.y() - lanes[1].first.y()), 7.87 / 2, 1e-9);
  expectValidLanes(band, 0.0, sensor);
}

TEST(SweepPattern, NarrowCellGetsOneCentredLane) {
  const Ring sliver = {{0, 0}, {20, 0}, {20, 1}, {0, 1}};
  const auto lanes = SweepPatternGenerator(FrustumSensor(4.0, 1.0, 0.4)).lanes(sliver, 0.0);
  ASSERT_EQ(lanes.size(), 1u);
  EXPECT_NEAR(lanes[0].first.y(), 0.5, 1e-9);
}

TEST(SweepPattern, ExtraLaneThroughUnseenCorner) {
  // A deep V at the bottom between two lanes: its tip is seen only by an extra lane.
  const Ring v = {{0, 0}, {3, -20}, {6, 0}, {6, 10}, {0, 10}};
  const FrustumSensor sensor(4.0, 1.0, 0.0);
  const auto lanes = SweepPatternGenerator(sensor).lanes(v, M_PI / 2);
  bool reaches_tip = false;
  for (const auto& lane : lanes) reaches_tip = reaches_tip || lane.first.y() < -19.0;
  EXPECT_TRUE(reaches_tip);
  expectValidLanes(v, M_PI / 2, sensor);
}

TEST(SweepPattern, MovesANearbyLaneThroughAnUnseenCornerRatherThanAddingOne) {
  // lake_30x30's cell left of the pentagon: its top corner (18.66, 26.21) lies beyond the
  // ends of both lanes. The upper lane can move up to it and stay within one sweep
  // distance of the lower one, so the cell keeps two lanes (an extra lane there made a
  // U-turn 1.4 m wide that a 1 m turning radius cannot smooth).
  const Ring cell = {{1, 26.2131}, {1, 16}, {17.382, 16}, {14.8292, 21.1056}, {18.6598, 26.2131}};
  const FrustumSensor sensor(12.8851, 1.59613, 0.4);
  const PolygonWithHoles area{{{1, 1}, {29, 1}, {29, 29}, {1, 29}},
                              {{{13, 16}, {13, 8}, {6, 8}, {6, 16}},
                               {{25.1437, 23.6195},
                                {23.8498, 17.1502},
                                {17.4472, 15.8696},
                                {14.8292, 21.1056},
                                {18.6598, 26.2131}}}};
  const auto lanes = SweepPatternGenerator(sensor, 0.0, area).lanes(cell, 0.0);
  ASSERT_EQ(lanes.size(), 2u);
  const double top = std::max(lanes[0].first.y(), lanes[1].first.y());
  EXPECT_NEAR(top, 26.2131, 1e-6);
  EXPECT_LE(std::abs(lanes[0].first.y() - lanes[1].first.y()), sensor.sweepDistance());
}

TEST(SweepPattern, LongSideSlantingAwayFromTheLanesIsSeenAlongItsWholeLength) {
  // Soak test seed 3640: a cell of the offset area whose lanes run parallel to its
  // left side (a decomposition cut) while its right side, a 46 m hull side, slants away
  // from them by 2 degrees. Its far corner moved the outer lane onto itself, a lane of no
  // length, and the next lane, 3.8 m from the side at its top, left a strip along the
  // side unseen (98.2 % reachable coverage).
  const Ring cell = {{18.64560583, -19.59048921},
                     {24.06481484, -20.03310404},
                     {10.10723561, 23.80470563},
                     {6.896713399, 22.82024788}};
  const PolygonWithHoles area{{{-24.26386516, -16.08585079},
                               {24.06481484, -20.03310404},
                               {10.10723561, 23.80470563},
                               {-21.74603609, 14.03738487}},
                              {}};
  const FrustumSensor sensor(5.379966478, 0.6664397847, 0.2056220888);
  const Point2 cut = cell[3] - cell[0];
  const double direction = std::atan2(cut.y(), cut.x());
  const auto lanes = SweepPatternGenerator(sensor, 0.0, area).lanes(cell, direction);
  expectCellSeen(cell, direction, sensor, lanes);
  // One lane more than before: the corner keeps its lane, the flank gets its own.
  EXPECT_LE(lanes.size(), 3u);
}

TEST(SweepPattern, RandomCellsWithSlantedSidesAreSeenEverywhere) {
  // Quadrilaterals with a flat top and bottom, at least a footprint wide, and two long
  // sides slanting up to 15 degrees away from the lanes, in random directions and sizes,
  // with random footprints. (A band narrower than the footprint and slanting across the
  // lanes can leave a wedge between the ends of two lanes; the decomposition sweeps such
  // a band along it.)
  std::mt19937 rng(3640);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_real_distribution<double> slant(-std::tan(0.26), std::tan(0.26));
  int cells = 0;
  while (cells < 300) {
    const double width = 2.0 + 10.9 * unit(rng);
    const FrustumSensor sensor(width, width * (0.05 + 0.2 * unit(rng)), 0.2 + 0.4 * unit(rng));
    const double height = 20.0 + 40.0 * unit(rng);
    const double bottom = width + 25.0 * unit(rng);
    const double left_top = height * slant(rng);
    const double right_top = bottom + height * slant(rng);
    const double direction = M_PI * (2.0 * unit(rng) - 1.0);
    if (right_top - left_top < width) continue;
    SCOPED_TRACE(::testing::Message() << "cell " << cells);
    ++cells;
    Ring cell;
    for (const Point2& p :
         std::vector<Point2>{{0.0, 0.0}, {bottom, 0.0}, {right_top, height}, {left_top, height}}) {
      cell.push_back(fromSweepFrame(p, direction));
    }
    if (signedArea(cell) < 0.0) std::reverse(cell.begin(), cell.end());
    const auto lanes = SweepPatternGenerator(sensor).lanes(cell, direction);
    expectValidLanes(cell, direction, sensor);
    expectCellSeen(cell, direction, sensor, lanes);
  }
}

TEST(SweepPattern, FourPatternsJoinLanesAtAlternatingEnds) {
  const Ring rectangle = {{0, 0}, {20, 0}, {20, 10}, {0, 10}};
  const SweepPatternGenerator generator(FrustumSensor(4.0, 1.0, 0.25));
  const auto patterns = generator.patterns(rectangle, 0.0, straight);
  ASSERT_EQ(patterns.size(), 4u);
  for (const SweepPattern& pattern : patterns) {
    ASSERT_EQ(pattern.path.size(), 8u);
    for (std::size_t i = 0; i + 1 < pattern.path.size(); i += 2) {
      // Lanes alternate direction along x.
      EXPECT_NEAR(std::abs(pattern.path[i + 1].x() - pattern.path[i].x()), 20.0, 1e-9);
      if (i + 2 < pattern.path.size()) {
        EXPECT_NEAR(pattern.path[i + 2].x(), pattern.path[i + 1].x(), 1e-9);
      }
    }
  }
  // The four patterns start at four different corners.
  for (std::size_t i = 0; i < patterns.size(); ++i) {
    for (std::size_t j = i + 1; j < patterns.size(); ++j) {
      EXPECT_GT((patterns[i].start() - patterns[j].start()).norm(), 1.0);
    }
  }
}

TEST(SweepPattern, RandomCellsHaveValidLanes) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> width(2.0, 13.0);
  std::uniform_real_distribution<double> overlap(0.0, 0.6);
  for (int trial = 0; trial < 100; ++trial) {
    const PolygonWithHoles map = testing::randomMap(rng, 120.0, 6, 2.0);
    const FrustumSensor sensor(width(rng), 1.0, overlap(rng));
    const Decomposition decomposition =
        computeBestDecomposition(map, DecompositionType::kBoustrophedon);
    for (const Cell& cell : decomposition.cells) {
      for (double direction : cell.sweep_directions) {
        SCOPED_TRACE(::testing::Message() << "trial " << trial << " direction " << direction);
        expectValidLanes(cell.polygon, direction, sensor);
      }
    }
  }
}

TEST(SweepPattern, LanesThroughAcuteCornersEndInsideTheCell) {
  // Slivers far from the origin, so that the corner tolerance (relative to the scale)
  // is large: a lane placed through an acute corner must still end inside the cell.
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> coordinate(-400.0, 400.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    const Point2 origin(coordinate(rng), coordinate(rng));
    const double heading = 2.0 * M_PI * unit(rng);
    const double length = 0.05 + 3.0 * unit(rng);
    const double opening = 0.02 + 0.6 * unit(rng);
    const Point2 b = origin + length * Point2(std::cos(heading), std::sin(heading));
    const Point2 c =
        origin + 0.7 * length * Point2(std::cos(heading + opening), std::sin(heading + opening));
    const Ring cell = {origin, b, c};
    const FrustumSensor sensor(0.2 + 2.0 * unit(rng), 0.5 + 3.0 * unit(rng), 0.7 * unit(rng));
    for (double direction : {heading, heading + opening, heading + 0.5 * opening}) {
      SCOPED_TRACE(::testing::Message() << "trial " << trial << " direction " << direction);
      expectValidLanes(cell, direction, sensor);
    }
  }
}

/// A 20 m x 10 m area whose right wall (x = 20) has a saw of teeth `depth` deep, and the
/// rectangle that BoundarySimplification makes of it within that depth.
struct SawWall {
  PolygonWithHoles exact;
  PolygonWithHoles simplified{{{0, 0}, {20, 0}, {20, 10}, {0, 10}}, {}};
};

SawWall sawWall(double depth) {
  SawWall wall;
  wall.exact.hull = {{0, 0}, {20, 0}};
  for (int k = 0; k < 10; ++k) {
    wall.exact.hull.emplace_back(20 + depth, k + 0.5);
    wall.exact.hull.emplace_back(20, k + 1.0);
  }
  wall.exact.hull.emplace_back(0, 10);
  return wall;
}

/// Lanes of a cell of a simplified area end where the lanes would end in the exact area: an
/// end on the simplified boundary goes on along the lane to the exact wall, inside the exact
/// area; an end on a wall that both share stays.
TEST(SweepPattern, LaneEndsOnASimplifiedBoundaryGoOnToTheExactWall) {
  const SawWall wall = sawWall(0.3);
  const FrustumSensor sensor(4.0, 1.0, 0.25);
  const SweepPatternGenerator generator(sensor, 0.0, wall.simplified, wall.exact);
  const auto lanes = generator.lanes(wall.simplified.hull, 0.0);
  ASSERT_FALSE(lanes.empty());
  bool some_beyond = false;
  for (const auto& [a, b] : lanes) {
    EXPECT_NEAR(a.x(), 0.0, 1e-9);
    EXPECT_NEAR(distanceToRing(b, wall.exact.hull), 0.0, 1e-9) << b.transpose();
    EXPECT_GE(b.x(), 20.0 - 1e-9);
    EXPECT_TRUE(segmentInside(wall.exact, a, b, 1e-9));
    some_beyond = some_beyond || b.x() > 20.01;
  }
  EXPECT_TRUE(some_beyond);
  // Without the exact area, the same lanes end on the simplified wall.
  for (const auto& [a, b] :
       SweepPatternGenerator(sensor, 0.0, wall.simplified).lanes(wall.simplified.hull, 0.0)) {
    EXPECT_NEAR(b.x(), 20.0, 1e-9);
  }
}

/// A lane end on a decomposition cut (not on the area's boundary) stays on the cut: going on
/// would sweep the neighbouring cell.
TEST(SweepPattern, LaneEndsOnACutDoNotGoOn) {
  const SawWall wall = sawWall(0.3);
  const FrustumSensor sensor(4.0, 1.0, 0.25);
  const SweepPatternGenerator generator(sensor, 0.0, wall.simplified, wall.exact);
  const Ring left_cell = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  for (const auto& [a, b] : generator.lanes(left_cell, 0.0)) {
    EXPECT_NEAR(a.x(), 0.0, 1e-9);
    EXPECT_NEAR(b.x(), 10.0, 1e-9);
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
