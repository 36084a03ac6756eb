#include "coverage_system/mission/polygon_sketch.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace kinematic_coverage::core {
namespace {

using VertexId = PolygonSketch::VertexId;
using RingKind = PolygonSketch::RingKind;

Ring square(double x0, double y0, double size) {
  return {{x0, y0}, {x0 + size, y0}, {x0 + size, y0 + size}, {x0, y0 + size}};
}

/// Clicks the vertices of `ring` and closes it, as the rviz tool does.
void drawRing(PolygonSketch& sketch, const Ring& ring) {
  for (const Point2& point : ring) sketch.addVertex(point);
  ASSERT_TRUE(sketch.closeRing());
}

TEST(PolygonSketch, HullAndHoleDrawnByClicksAreExactlyThoseRings) {
  PolygonSketch sketch;
  drawRing(sketch, square(2, 2, 26));
  drawRing(sketch, square(12, 12, 6));
  EXPECT_EQ(sketch.hull(), square(2, 2, 26));
  ASSERT_EQ(sketch.holes().size(), 1u);
  EXPECT_EQ(sketch.holes()[0], square(12, 12, 6));
  EXPECT_TRUE(sketch.openRing().empty());
  EXPECT_EQ(sketch.validity().value_or(""), "");
  const auto polygon = sketch.completePolygon();
  ASSERT_TRUE(polygon.has_value());
  EXPECT_EQ(polygon->hull, square(2, 2, 26));
  ASSERT_EQ(polygon->holes.size(), 1u);
  EXPECT_EQ(polygon->holes[0], square(12, 12, 6));
}

TEST(PolygonSketch, NothingIsValidUntilTheHullIsClosed) {
  PolygonSketch sketch;
  EXPECT_FALSE(sketch.hasHull());
  EXPECT_TRUE(sketch.validity().has_value());
  EXPECT_FALSE(sketch.completePolygon().has_value());
  const Ring hull = square(0, 0, 10);
  for (const Point2& point : hull) {
    sketch.addVertex(point);
    EXPECT_FALSE(sketch.hasHull());
    EXPECT_FALSE(sketch.completePolygon().has_value());
  }
  EXPECT_EQ(sketch.openRing(), hull);
  ASSERT_TRUE(sketch.closeRing());
  EXPECT_TRUE(sketch.hasHull());
  EXPECT_TRUE(sketch.completePolygon().has_value());
}

TEST(PolygonSketch, AnOpenRingIsNotPublishedUntilClosed) {
  PolygonSketch sketch;
  drawRing(sketch, square(0, 0, 10));
  sketch.addVertex({2, 2});
  sketch.addVertex({4, 2});
  EXPECT_FALSE(sketch.closeRing()) << "a ring needs 3 vertices";
  EXPECT_EQ(sketch.openRing().size(), 2u);
  sketch.addVertex({4, 4});
  // The closed rings stay valid; the polygon is complete only once the hole is closed.
  EXPECT_EQ(sketch.validity().value_or(""), "");
  EXPECT_FALSE(sketch.completePolygon().has_value());
  ASSERT_TRUE(sketch.closeRing());
  ASSERT_TRUE(sketch.completePolygon().has_value());
  EXPECT_EQ(sketch.completePolygon()->holes.size(), 1u);
}

TEST(PolygonSketch, CancelDropsOnlyTheOpenRing) {
  PolygonSketch sketch;
  drawRing(sketch, square(0, 0, 10));
  sketch.addVertex({2, 2});
  sketch.addVertex({4, 2});
  sketch.cancelOpenRing();
  EXPECT_TRUE(sketch.openRing().empty());
  EXPECT_EQ(sketch.hull(), square(0, 0, 10));
  EXPECT_TRUE(sketch.holes().empty());
  EXPECT_TRUE(sketch.completePolygon().has_value());
}

TEST(PolygonSketch, SelfIntersectingHullIsReportedWithTheValidatorsMessage) {
  PolygonSketch sketch;
  drawRing(sketch, {{0, 0}, {10, 10}, {10, 0}, {0, 10}});  // a bow-tie
  const auto problem = sketch.validity();
  ASSERT_TRUE(problem.has_value());
  EXPECT_EQ(problem->rfind("hull is self-intersecting: ", 0), 0u) << *problem;
  EXPECT_FALSE(sketch.completePolygon().has_value());
}

TEST(PolygonSketch, HoleOutsideTheHullIsReportedWithTheValidatorsMessage) {
  PolygonSketch sketch;
  drawRing(sketch, square(0, 0, 10));
  drawRing(sketch, square(3, 3, 2));
  drawRing(sketch, square(20, 20, 2));
  EXPECT_EQ(sketch.validity().value_or(""), "hole 1 lies entirely outside the hull");
  EXPECT_FALSE(sketch.completePolygon().has_value());
}

TEST(PolygonSketch, MovingAVertexChangesOnlyThatVertexAndIsRevalidated) {
  PolygonSketch sketch;
  drawRing(sketch, square(0, 0, 10));
  drawRing(sketch, square(4, 4, 2));
  // Hole 0's vertex 1, (6, 4), dragged across its opposite edge makes it self-intersecting.
  const VertexId dragged{RingKind::kHole, 0, 1};
  sketch.moveVertex(dragged, {3, 5});
  EXPECT_EQ(sketch.vertex(dragged), Point2(3, 5));
  EXPECT_EQ(sketch.hull(), square(0, 0, 10));
  const auto problem = sketch.validity();
  ASSERT_TRUE(problem.has_value());
  EXPECT_EQ(problem->rfind("hole 0 is self-intersecting: ", 0), 0u) << *problem;
  EXPECT_FALSE(sketch.completePolygon().has_value());
  sketch.moveVertex(dragged, {6, 4});
  EXPECT_EQ(sketch.holes()[0], square(4, 4, 2));
  EXPECT_TRUE(sketch.completePolygon().has_value());
}

TEST(PolygonSketch, NearestVertexFindsTheClosestWithinTheTolerance) {
  PolygonSketch sketch;
  drawRing(sketch, square(0, 0, 10));
  drawRing(sketch, square(4, 4, 2));
  sketch.addVertex({8, 8});
  const auto hole_vertex = sketch.nearestVertex({6.1, 6.2}, 0.5);
  ASSERT_TRUE(hole_vertex.has_value());
  EXPECT_EQ(hole_vertex->ring, RingKind::kHole);
  EXPECT_EQ(hole_vertex->hole, 0u);
  EXPECT_EQ(hole_vertex->index, 2u);
  const auto open_vertex = sketch.nearestVertex({8.2, 8}, 0.5);
  ASSERT_TRUE(open_vertex.has_value());
  EXPECT_EQ(open_vertex->ring, RingKind::kOpen);
  EXPECT_EQ(open_vertex->index, 0u);
  const auto hull_vertex = sketch.nearestVertex({10, 0.5}, 0.5);
  ASSERT_TRUE(hull_vertex.has_value());
  EXPECT_EQ(hull_vertex->ring, RingKind::kHull);
  EXPECT_EQ(hull_vertex->index, 1u);
  EXPECT_FALSE(sketch.nearestVertex({5, 2}, 0.5).has_value());
  EXPECT_THROW(sketch.vertex({RingKind::kHole, 1, 0}), std::out_of_range);
}

TEST(PolygonSketch, DeletingAVertexShrinksItsRing) {
  PolygonSketch sketch;
  drawRing(sketch, {{0, 0}, {10, 0}, {10, 10}, {5, 12}, {0, 10}});
  sketch.deleteVertex({RingKind::kHull, 0, 3});
  EXPECT_EQ(sketch.hull(), square(0, 0, 10));
  EXPECT_TRUE(sketch.completePolygon().has_value());
  sketch.addVertex({2, 2});
  sketch.addVertex({4, 2});
  sketch.deleteVertex({RingKind::kOpen, 0, 0});
  EXPECT_EQ(sketch.openRing(), Ring{Point2(4, 2)});
  EXPECT_THROW(sketch.deleteVertex({RingKind::kOpen, 0, 1}), std::out_of_range);
}

TEST(PolygonSketch, AClosedRingLeftWithTwoVerticesIsRemoved) {
  PolygonSketch sketch;
  drawRing(sketch, square(0, 0, 10));
  drawRing(sketch, {{1, 1}, {2, 1}, {2, 2}});
  drawRing(sketch, square(5, 5, 2));
  sketch.deleteVertex({RingKind::kHole, 0, 0});
  ASSERT_EQ(sketch.holes().size(), 1u) << "hole 0 removed, hole 1 renumbered";
  EXPECT_EQ(sketch.holes()[0], square(5, 5, 2));
  EXPECT_TRUE(sketch.completePolygon().has_value());
  drawRing(sketch, {{0, 0}, {10, 0}, {10, 10}});
  ASSERT_EQ(sketch.holes().size(), 2u);
  // A removed hull keeps the holes; the next ring closed is the hull.
  sketch.deleteVertex({RingKind::kHull, 0, 0});
  sketch.deleteVertex({RingKind::kHull, 0, 0});
  EXPECT_FALSE(sketch.hasHull());
  EXPECT_EQ(sketch.holes().size(), 2u);
  EXPECT_FALSE(sketch.completePolygon().has_value());
  drawRing(sketch, square(0, 0, 10));
  EXPECT_EQ(sketch.hull(), square(0, 0, 10));
  EXPECT_EQ(sketch.holes().size(), 2u);
}

}  // namespace
}  // namespace kinematic_coverage::core
