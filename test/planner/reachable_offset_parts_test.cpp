#include "coverage_system/planner/reachable_offset_parts.h"

#include <gtest/gtest.h>

#include <vector>

#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"
#include "test/support/test_shapes.h"

namespace kinematic_coverage::core {
namespace {

/// The two rooms of a strait exactly two wall distances wide are reachable from either;
/// with a 1.1 m wall distance the strait's 1 m clearance keeps only the start's room, unless
/// gap_clearance allows 1 m or `offset_parts: largest` counts every part.
TEST(ReachableOffsetParts, ArePartsTheStartsPartReachesThroughGapsKeepingTheGapClearance) {
  const PolygonWithHoles rooms = testing::twoRoomsJoinedByATwoMetreStrait();
  PlannerParameters parameters;
  parameters.wall_distance = 1.0;
  const double both = area(computeOffsetFreeArea(rooms, 1.0).parts);
  EXPECT_NEAR(area(reachableOffsetParts(rooms, planningOptionsOf(parameters), {5, 5})), both, 1e-9);

  parameters.wall_distance = 1.1;
  const std::vector<PolygonWithHoles> parts = computeOffsetFreeArea(rooms, 1.1).parts;
  ASSERT_EQ(parts.size(), 2u);
  for (const Point2& start : {Point2(5, 5), Point2(21, 5)}) {
    const std::vector<PolygonWithHoles> reachable =
        reachableOffsetParts(rooms, planningOptionsOf(parameters), start);
    ASSERT_EQ(reachable.size(), 1u);
    EXPECT_TRUE(contains(reachable.front(), start));
    EXPECT_EQ(nearestPart(parts, start), contains(parts[0], start) ? 0u : 1u);
  }
  parameters.gap_clearance = 1.0;
  EXPECT_EQ(reachableOffsetParts(rooms, planningOptionsOf(parameters), {5, 5}).size(), 2u);
  parameters.gap_clearance = kClearanceOfWallDistance;
  parameters.offset_parts = "largest";
  EXPECT_EQ(reachableOffsetParts(rooms, planningOptionsOf(parameters), {5, 5}).size(), 2u);
}

}  // namespace
}  // namespace kinematic_coverage::core
