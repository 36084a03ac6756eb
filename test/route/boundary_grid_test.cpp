#include "polygon_coverage_ros_bridge/route/boundary_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "test/route/route_test_maps.h"
#include "test/support/random_polygons.h"

namespace kinematic_coverage::core {
namespace {

PolygonWithHoles squareWithHole() {
  return {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{4, 4}, {4, 6}, {6, 6}, {6, 4}}}};
}

/// Two square holes touching at the pinch point (5, 5).
PolygonWithHoles holesTouchingAtVertex() {
  return {{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
          {{{2, 2}, {2, 5}, {5, 5}, {5, 2}}, {{5, 5}, {5, 8}, {8, 8}, {8, 5}}}};
}

/// A hull visiting (5, 5) twice: two square lobes joined at a corner.
PolygonWithHoles hullPinchedAtVertex() {
  return {{{0, 0}, {5, 0}, {5, 5}, {10, 5}, {10, 10}, {5, 10}, {5, 5}, {0, 5}}, {}};
}

/// A triangular hole whose apex (5, 0) lies on the hull's bottom edge.
PolygonWithHoles holeTouchingHullEdge() {
  return {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{5, 0}, {3, 4}, {7, 4}}}};
}

TEST(BoundaryGrid, SegmentsAgainstOneHole) {
  const BoundaryGrid grid(squareWithHole());
  EXPECT_TRUE(grid.segmentInside({1, 1}, {9, 1}));
  EXPECT_FALSE(grid.segmentInside({1, 5}, {9, 5}));
  EXPECT_FALSE(grid.segmentInside({1, 3}, {9, 7}));
  // Along the hole's edge and beyond its vertices; along the hull's edge.
  EXPECT_TRUE(grid.segmentInside({4, 1}, {4, 9}));
  EXPECT_TRUE(grid.segmentInside({0, 0}, {10, 0}));
  EXPECT_TRUE(grid.segmentInside({0, 0}, {0, 10}));
  // Touching the hole at one corner only (from outside it) is inside.
  EXPECT_TRUE(grid.segmentInside({2, 6}, {6, 2}));
  EXPECT_TRUE(grid.segmentInside({3, 5}, {5, 3}));
  EXPECT_TRUE(grid.segmentInside({3, 5}, {5, 7}));
  EXPECT_TRUE(grid.segmentInside({2, 4}, {6, 8}));
  EXPECT_TRUE(grid.segmentInside({2, 8}, {4, 6}));  // ends at a corner
  EXPECT_TRUE(grid.segmentInside({2, 4}, {4, 2}));
  // Through two opposite corners, or just past one, crosses the hole.
  EXPECT_FALSE(grid.segmentInside({2, 8}, {8, 2}));
  EXPECT_FALSE(grid.segmentInside({1, 1}, {9, 9}));
  EXPECT_FALSE(grid.segmentInside({1, 7}, {9, 3}));
  EXPECT_FALSE(grid.segmentInside({3, 5.001}, {5, 3.001}));
}

TEST(BoundaryGrid, BoundaryEndsGoInOnlyOnTheFreeSide) {
  const BoundaryGrid grid(squareWithHole());
  // From a point on the hole's left edge: outwards is free, inwards is not.
  EXPECT_TRUE(grid.segmentInside({4, 5}, {1, 5}));
  EXPECT_FALSE(grid.segmentInside({4, 5}, {5, 5.5}));
  EXPECT_FALSE(grid.segmentInside({4, 5}, {6, 5}));  // both ends on the hole
  EXPECT_TRUE(grid.segmentInside({4, 5}, {4, 6}));   // along its edge
  // From a corner of the hole.
  EXPECT_TRUE(grid.segmentInside({4, 4}, {1, 1}));
  EXPECT_TRUE(grid.segmentInside({4, 4}, {9, 4}));
  EXPECT_FALSE(grid.segmentInside({4, 4}, {6, 6}));
  // Hull corner to hull corner across the hole, and along the hull.
  EXPECT_FALSE(grid.segmentInside({0, 0}, {10, 10}));
  EXPECT_TRUE(grid.segmentInside({0, 0}, {10, 0}));
  // Boundary points a rounding error off the boundary behave like boundary points.
  EXPECT_TRUE(grid.segmentInside({4.0 - 1e-13, 5}, {1, 9}));
  EXPECT_TRUE(grid.segmentInside({10.0 + 1e-13, 5}, {1, 9}));
}

TEST(BoundaryGrid, ContainsAndContacts) {
  const BoundaryGrid grid(squareWithHole());
  EXPECT_TRUE(grid.contains({1, 1}));
  EXPECT_TRUE(grid.contains({4, 5}));
  EXPECT_FALSE(grid.contains({5, 5}));
  EXPECT_FALSE(grid.contains({-1, 5}));
  EXPECT_FALSE(grid.contains({std::numeric_limits<double>::quiet_NaN(), 5}));
  EXPECT_EQ(grid.contactOf({1, 1}).cluster, -1);
  EXPECT_TRUE(grid.contactOf({1, 1}).edges.empty());
  EXPECT_EQ(grid.contactOf({4, 5}).edges.size(), 1u);
  const BoundaryGrid::Contact corner = grid.contactOf({6, 6});
  ASSERT_GE(corner.cluster, 0);
  EXPECT_EQ(grid.clusterPosition(corner.cluster), Point2(6, 6));
  // The hole's four corners are the only bends (the hull is convex).
  EXPECT_EQ(grid.bendClusters().size(), 4u);
}

TEST(BoundaryGrid, PinchBetweenTwoHoles) {
  const BoundaryGrid grid(holesTouchingAtVertex());
  // Through the pinch from free quadrant to free quadrant: inside.
  EXPECT_TRUE(grid.segmentInside({2, 8}, {8, 2}));
  EXPECT_TRUE(grid.segmentInside({1, 9}, {9, 1}));
  // Through the pinch from hole to hole, and beside it through a hole.
  EXPECT_FALSE(grid.segmentInside({1, 1}, {9, 9}));
  EXPECT_FALSE(grid.segmentInside({3, 8}, {8, 3}));
  // From the pinch point itself.
  EXPECT_TRUE(grid.segmentInside({5, 5}, {9, 1}));
  EXPECT_TRUE(grid.segmentInside({5, 5}, {1, 9}));
  EXPECT_FALSE(grid.segmentInside({5, 5}, {9, 9}));
  EXPECT_FALSE(grid.segmentInside({5, 5}, {1, 1}));
  // Along the holes' edges through the pinch.
  EXPECT_TRUE(grid.segmentInside({5, 1}, {5, 9}));
  EXPECT_TRUE(grid.segmentInside({1, 5}, {9, 5}));
  const std::vector<int> bends = grid.bendClusters();
  EXPECT_TRUE(std::any_of(bends.begin(), bends.end(),
                          [&](int k) { return grid.clusterPosition(k) == Point2(5, 5); }));
}

TEST(BoundaryGrid, PinchOfTheHull) {
  const BoundaryGrid grid(hullPinchedAtVertex());
  EXPECT_TRUE(grid.segmentInside({1, 1}, {9, 9}));
  EXPECT_TRUE(grid.segmentInside({5, 5}, {9, 6}));
  EXPECT_TRUE(grid.segmentInside({4, 1}, {5, 5}));
  EXPECT_FALSE(grid.segmentInside({1, 4}, {6, 9}));
  EXPECT_FALSE(grid.segmentInside({4, 1}, {9, 6}));  // passes (5, 2): outside
  EXPECT_FALSE(grid.contains({2, 8}));
  const std::vector<int> bends = grid.bendClusters();
  ASSERT_EQ(bends.size(), 1u);
  EXPECT_EQ(grid.clusterPosition(bends[0]), Point2(5, 5));
}

TEST(BoundaryGrid, HoleTouchingTheHullEdge) {
  const BoundaryGrid grid(holeTouchingHullEdge());
  EXPECT_FALSE(grid.segmentInside({1, 1}, {9, 1}));
  EXPECT_TRUE(grid.segmentInside({1, 1}, {5, 0}));
  EXPECT_TRUE(grid.segmentInside({5, 0}, {9, 1}));
  EXPECT_FALSE(grid.segmentInside({5, 0}, {5, 2}));
  // Along the hull edge through the touching point: on the boundary, inside.
  EXPECT_TRUE(grid.segmentInside({1, 0}, {9, 0}));
  const std::vector<int> bends = grid.bendClusters();
  EXPECT_TRUE(std::any_of(bends.begin(), bends.end(),
                          [&](int k) { return grid.clusterPosition(k) == Point2(5, 0); }));
}

TEST(BoundaryGrid, BoundaryEndJustPastAConvexCornerSeesAlongTheOtherEdge) {
  // An end on the corner's outgoing edge, past the corner's tolerance: the segment back
  // along the incoming edge passes the corner within the tolerance, and its short piece
  // from the corner to the end runs off that edge's ray by the corner's whole turn angle
  // (the regression: such sweep-lane ends saw no node and got an infinite cost).
  const double bend = 0.1;
  const BoundaryGrid grid(testing::bentCorridorMap(bend));
  const Point2 heading(std::cos(bend), std::sin(bend));
  const Point2 corner(80, 20);
  const Point2 end = corner + 3.0 * grid.tolerance() * heading;
  ASSERT_EQ(grid.contactOf(end).cluster, -1);
  EXPECT_TRUE(grid.segmentInside(end, {50, 20}));
  EXPECT_TRUE(grid.segmentInside({50, 20}, end));
  EXPECT_TRUE(grid.segmentInside(end, {50, 22}));
  EXPECT_TRUE(grid.segmentInside(end, {60, 20.5}));
  EXPECT_FALSE(grid.segmentInside(end, {10, 5}));   // through the room's wall
  EXPECT_FALSE(grid.segmentInside(end, {40, 19}));  // through the mouth's lower corner
  // Farther along the edge, the corner is clear of the same segments.
  const Point2 farther = corner + 1e-3 * heading;
  EXPECT_TRUE(grid.segmentInside(farther, {50, 20}));
  EXPECT_FALSE(grid.segmentInside(farther, {40, 19}));
}

TEST(BoundaryGrid, BoundaryEndJustPastAReflexCornerSeesAcrossIt) {
  // The offset free area of CoveragePlanner.LanesThroughAcuteCornersEndInsideTheOffsetArea:
  // a lane end on the edge leaving the reflex corner p, 2.7e-8 m past it (beyond the
  // corner's tolerance), and a far end whose segment passes p on its free side within the
  // tolerance. Judged along the segment, the piece from p to the end pointed into p's
  // wall; from p itself it runs along the edge (the regression: no straight leg, and with
  // the tangent visibility graph no route at all).
  const PolygonWithHoles area = {{{15.830035230078465, 15.11743803385616},
                                  {17.738827395950466, 15.753702089146827},
                                  {16.305415041149899, 15.753702089146827},
                                  {12.80541504114899, 24.753702089146827},
                                  {6.5810833464674943, 24.753702089146827},
                                  {14.746297910853173, 16.199667783600489},
                                  {14.746297910853173, 15.223340278618707},
                                  {14.943317848464176, 15.026320341008613},
                                  {15.366007046015511, 14.885423941824229}},
                                 {}};
  const BoundaryGrid grid(area);
  const Point2 end(15.830035256038965, 15.11743804250966);
  const Point2 far_end(6.6317831430797565, 24.753702089146827);
  ASSERT_EQ(grid.contactOf(end).cluster, -1);
  ASSERT_GT((end - area.hull.front()).norm(), grid.tolerance());
  EXPECT_TRUE(grid.segmentInside(end, far_end));
  EXPECT_TRUE(grid.segmentInside(far_end, end));
  // Across the corner's wall, from the same end: outside.
  EXPECT_FALSE(grid.segmentInside(end, {14.9, 15.0}));
}

TEST(BoundaryGrid, BoundaryEndInAReflexCornersSliverGoesToBothFreeSides) {
  // Near the tip of a thin wall spike, a point on one side is within the tolerance of the
  // other side too; the free directions there are the union of the two edges' free sides
  // (the tip's rays), not their intersection.
  const double half_base = 0.003;
  const BoundaryGrid grid(testing::wallSpikeMap(half_base));
  const Point2 tip(5, 6);
  const Point2 down_left = (Point2(5 - half_base, 0) - tip).normalized();
  const Point2 down_right = (Point2(5 + half_base, 0) - tip).normalized();
  const double apex = std::acos(down_left.dot(down_right));
  const Point2 into_wall(-down_left.y(), down_left.x());
  const std::vector<Point2> sliver_points = {
      tip + 2.0 * grid.tolerance() * down_left + 1e-13 * into_wall,
      tip + 0.5 * grid.tolerance() / std::sin(apex) * down_left};
  for (const Point2& end : sliver_points) {
    SCOPED_TRACE(::testing::Message() << "end " << end.transpose());
    ASSERT_GT((end - tip).norm(), grid.tolerance());
    ASSERT_LE(distanceToSegment(end, tip, tip + down_right), grid.tolerance());
    EXPECT_TRUE(grid.contains(end));
    const BoundaryGrid::Contact contact = grid.contactOf(end);
    EXPECT_EQ(contact.cluster, grid.contactOf(tip).cluster);  // the tip's rays judge
    EXPECT_EQ(contact.edges.size(), 2u);
    EXPECT_TRUE(grid.segmentInside(end, {1, 5}));  // the own edge's free side
    EXPECT_TRUE(grid.segmentInside(end, {1, 1}));
    EXPECT_TRUE(grid.segmentInside(end, {9, 5}));  // across the sliver, thinner than tolerance
    EXPECT_TRUE(grid.segmentInside(end, {5, 9}));  // over the tip
    EXPECT_TRUE(grid.segmentInside(end, tip));
  }
  // Lower down the spike is wide: crossing it leaves the area.
  const Point2 low = tip + 3.0 * down_left;
  EXPECT_TRUE(grid.segmentInside(low, {1, 5}));
  EXPECT_FALSE(grid.segmentInside(low, {9, 5}));
}

TEST(BoundaryGrid, BoundaryEndInAConvexCornersSliverKeepsBothEdgesSides) {
  // In a thin needle of free area, a point near the tip is within the tolerance of both
  // edges: it may go along either edge, also a short way, but not out of the needle.
  const double half_base = 0.003;
  const BoundaryGrid grid(testing::freeNeedleMap(half_base));
  const Point2 tip(16, 5);
  const Point2 back_low = (Point2(10, 5 - half_base) - tip).normalized();
  const Point2 back_high = (Point2(10, 5 + half_base) - tip).normalized();
  const double apex = std::acos(back_low.dot(back_high));
  const Point2 end = tip + 0.5 * grid.tolerance() / std::sin(apex) * back_low;
  ASSERT_LE(distanceToSegment(end, tip, tip + back_high), grid.tolerance());
  EXPECT_EQ(grid.contactOf(end).cluster, -1);  // both edges' free sides, intersected
  EXPECT_EQ(grid.contactOf(end).edges.size(), 2u);
  EXPECT_TRUE(grid.segmentInside(end, tip + 1e-4 * back_high));
  EXPECT_TRUE(grid.segmentInside(end, tip + 1e-4 * back_low));
  EXPECT_TRUE(grid.segmentInside(end, tip + 1e-4 * back_high + 1e-9 * back_low));
  EXPECT_TRUE(grid.segmentInside(end, {5, 5}));
  EXPECT_FALSE(grid.segmentInside(end, {9, 9}));                  // over the needle's root
  EXPECT_FALSE(grid.segmentInside(end, {9, 5 + 2 * half_base}));  // through its upper edge
  EXPECT_FALSE(grid.segmentInside(end, {9, 5 - 2 * half_base}));  // through its lower edge
  // From a point most of a tolerance beside the tip, short segments along the edges turn
  // off the edges' rays by far more than a long one could.
  const Point2 near_tip = tip + Point2(0, -0.7 * grid.tolerance());
  ASSERT_EQ(grid.contactOf(near_tip).cluster, grid.contactOf(tip).cluster);
  EXPECT_TRUE(grid.segmentInside(near_tip, tip + 1e-5 * back_high));
  EXPECT_TRUE(grid.segmentInside(near_tip, tip + 1e-5 * back_low));
  EXPECT_FALSE(grid.segmentInside(near_tip, {9, 9}));
}

TEST(BoundaryGrid, OrientationAndRepeatedVerticesAreNormalized) {
  PolygonWithHoles polygon = squareWithHole();
  std::reverse(polygon.hull.begin(), polygon.hull.end());
  std::reverse(polygon.holes[0].begin(), polygon.holes[0].end());
  polygon.hull.insert(polygon.hull.begin() + 1, polygon.hull[1]);
  const BoundaryGrid grid(polygon);
  EXPECT_GT(signedArea(grid.polygon().hull), 0.0);
  EXPECT_LT(signedArea(grid.polygon().holes[0]), 0.0);
  EXPECT_EQ(grid.polygon().hull.size(), 4u);
  EXPECT_FALSE(grid.segmentInside({1, 5}, {9, 5}));
  EXPECT_TRUE(grid.segmentInside({1, 1}, {9, 1}));
}

TEST(BoundaryGrid, RejectsDegenerateRings) {
  EXPECT_THROW(BoundaryGrid({{{0, 0}, {1, 0}}, {}}), InvalidInputError);
  EXPECT_THROW(BoundaryGrid({{{0, 0}, {1, 0}, {2, 0}}, {}}), InvalidInputError);
  EXPECT_THROW(BoundaryGrid({{{0, 0}, {1, 0}, {0, std::numeric_limits<double>::infinity()}}, {}}),
               InvalidInputError);
  EXPECT_THROW(BoundaryGrid({{{0, 0}, {10, 0}, {10, 10}}, {{{1, 1}, {1, 1}, {2, 2}}}}),
               InvalidInputError);
}

TEST(BoundaryGrid, AHoleWithinTheToleranceIsAPointThatBlocksNothing) {
  // Every test allows the tolerance (1e-9 of the extent), so a hole that small is a point.
  const BoundaryGrid grid(
      {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{5, 5}, {5 + 1e-12, 5}, {5, 5 + 1e-12}}}});
  EXPECT_TRUE(grid.polygon().holes.empty());
  EXPECT_TRUE(grid.segmentInside({1, 1}, {9, 9}));
}

TEST(BoundaryGrid, ToleranceFollowsTheCoordinatesAsWellAsTheExtent) {
  // Rounding grows with the coordinates: a small polygon far from the origin gets the
  // tolerance of its coordinates, a large one near it that of its extent.
  EXPECT_DOUBLE_EQ(BoundaryGrid({{{15, 15}, {15.5, 15}, {15.5, 15.5}, {15, 15.5}}, {}}).tolerance(),
                   1e-9 * 15.5);
  EXPECT_DOUBLE_EQ(BoundaryGrid({{{-20, 0}, {20, 0}, {20, 10}, {-20, 10}}, {}}).tolerance(),
                   1e-9 * 40.0);
  EXPECT_DOUBLE_EQ(BoundaryGrid({{{0, 0}, {0.5, 0}, {0.5, 0.5}}, {}}).tolerance(), 1e-9);
}

TEST(BoundaryGrid, ChordsNearAConvexCornerAreInside) {
  // planner_fuzzer: an offset free area 0.57 m across at (15, 15), and two lane ends on the
  // edges of its bottom corner, 2.6e-8 m and 1.1e-7 m from it. The chord between them
  // passes the corner within the tolerance (1.56e-8 m), on its free side; it was refused
  // because its directions were judged from the corner's rays alone, and the solve stage
  // met an infinite transition cost.
  const BoundaryGrid grid({{{15.022278871488929, 15.000000000000002},
                            {15.366007046015762, 14.885423941824392},
                            {15.595159162366983, 15},
                            {15.36600704601576, 15.114576058175611}},
                           {}});
  const Point2 a(15.36600702135765, 14.885423950043762);
  const Point2 b(15.36600714464821, 14.885423991140616);
  EXPECT_TRUE(grid.segmentInside(a, b));
  EXPECT_TRUE(grid.segmentInside(b, a));
  // planner_fuzzer: a chord from one corner nearly along an edge to just past the next
  // corner on the following edge, 11.5 m long, passing that corner at about the tolerance.
  const BoundaryGrid quadrilateral({{{15.838964377377614, 15.437669685194587},
                                     {11.527633899657719, 12.03833985771821},
                                     {19.627632462885003, 6.5487520446419731},
                                     {26.819140787604042, 19.051311122172542}},
                                    {}});
  const Point2 at_corner(26.819140778875269, 19.051311119299854);
  const Point2 past_corner(15.838964315913149, 15.437669636732057);
  EXPECT_TRUE(quadrilateral.segmentInside(at_corner, past_corner));
  EXPECT_TRUE(quadrilateral.segmentInside(past_corner, at_corner));
  // The same at other distances from the corner, in tolerances.
  const Point2 bottom = grid.polygon().hull[1];
  const Point2 to_left = (grid.polygon().hull[0] - bottom).normalized();
  const Point2 to_right = (grid.polygon().hull[2] - bottom).normalized();
  for (double from_a : {0.5, 1.0, 1.7, 3.0, 10.0, 1000.0}) {
    for (double from_b : {0.5, 1.0, 1.7, 3.0, 7.0, 10.0, 1000.0}) {
      const Point2 on_left = bottom + from_a * grid.tolerance() * to_left;
      const Point2 on_right = bottom + from_b * grid.tolerance() * to_right;
      EXPECT_TRUE(grid.segmentInside(on_left, on_right)) << from_a << ", " << from_b;
      EXPECT_TRUE(grid.segmentInside(on_right, on_left)) << from_a << ", " << from_b;
    }
  }
}

TEST(BoundaryGrid, AgreesWithPlanarGeometryOnRandomSegments) {
  std::mt19937 rng(11);
  int disagreements = 0;
  int blocked = 0;
  int total = 0;
  for (int map_index = 0; map_index < 30; ++map_index) {
    const PolygonWithHoles map = testing::randomMap(rng, 100.0, 15, 1.0);
    const BoundaryGrid grid(map);
    std::uniform_real_distribution<double> coordinate(-50.0, 50.0);
    std::vector<Point2> points;
    while (points.size() < 60) {
      const Point2 p(coordinate(rng), coordinate(rng));
      if (contains(map, p)) points.push_back(p);
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
      for (std::size_t j = i + 1; j < points.size(); ++j) {
        const bool ours = grid.segmentInside(points[i], points[j]);
        const bool reference = segmentInside(map, points[i], points[j], 0.0);
        disagreements += ours != reference;
        blocked += !ours;
        ++total;
      }
    }
  }
  EXPECT_EQ(disagreements, 0);
  EXPECT_GT(blocked, total / 10);
}

TEST(BoundaryGrid, ContainsAgreesWithPlanarGeometryOnAndOffTheBoundary) {
  // Random maps with holes, points anywhere, on vertices and edges, and a little off them
  // (within the tolerance and beyond it), against the brute-force test with the tolerance.
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> coordinate(-60.0, 60.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int inside = 0;
  int total = 0;
  for (int map_index = 0; map_index < 30; ++map_index) {
    const PolygonWithHoles map = testing::randomMap(rng, 100.0, 15, 1.0);
    const BoundaryGrid grid(map);
    const PolygonWithHoles& rings = grid.polygon();
    std::vector<Point2> points;
    for (int k = 0; k < 400; ++k) points.emplace_back(coordinate(rng), coordinate(rng));
    std::vector<const Ring*> all = {&rings.hull};
    for (const Ring& hole : rings.holes) all.push_back(&hole);
    for (const Ring* ring : all) {
      for (std::size_t i = 0; i < ring->size(); ++i) {
        const Point2& a = (*ring)[i];
        const Point2& b = (*ring)[(i + 1) % ring->size()];
        const Point2 normal = Point2(b.y() - a.y(), a.x() - b.x()).normalized();
        const Point2 on = a + unit(rng) * (b - a);
        points.push_back(a);
        points.push_back(on);
        for (const double off : {0.5, 2.0, 1e3}) {
          points.push_back(on + off * grid.tolerance() * normal);
          points.push_back(on - off * grid.tolerance() * normal);
        }
      }
    }
    for (const Point2& p : points) {
      const bool reference = contains(rings, p, grid.tolerance());
      EXPECT_EQ(grid.contains(p), reference) << p.transpose();
      inside += reference;
      ++total;
    }
  }
  EXPECT_GT(inside, total / 4);
  EXPECT_LT(inside, 3 * total / 4);
}

}  // namespace
}  // namespace kinematic_coverage::core
