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

/// A 20 m x 10 m room joined by a strait 2 m wide (1 m clearance) to a 4 m x 5 m room.
/// A start in the strait's mouth, 1 m from its walls, lies nearest the small room's part,
/// but reaches the large one without coming nearer the walls than it starts: the large
/// room's group is the start's. A start 1.2 m from the small room's walls, where the strait
/// is narrower than that, reaches the small room only.
TEST(ReachableOffsetParts, FromTheWallBandTheStartsGroupIsTheLargestItReachesAtItsClearance) {
  const PolygonWithHoles rooms = {{{0, 0},
                                   {20, 0},
                                   {20, 4},
                                   {22, 4},
                                   {22, 2.5},
                                   {26, 2.5},
                                   {26, 7.5},
                                   {22, 7.5},
                                   {22, 6},
                                   {20, 6},
                                   {20, 10},
                                   {0, 10}},
                                  {}};
  PlannerParameters parameters;
  parameters.wall_distance = 1.1;
  const std::vector<PolygonWithHoles> parts = computeOffsetFreeArea(rooms, 1.1).parts;
  ASSERT_EQ(parts.size(), 2u);
  const Point2 in_the_mouth(21.8, 5.0);
  EXPECT_EQ(nearestPart(parts, in_the_mouth), 1u);
  const std::vector<PolygonWithHoles> reachable =
      reachableOffsetParts(rooms, planningOptionsOf(parameters), in_the_mouth);
  ASSERT_EQ(reachable.size(), 1u);
  EXPECT_NEAR(area(reachable.front()), area(parts[0]), 1e-9);

  parameters.wall_distance = 1.5;
  const Point2 in_the_small_room(23.2, 6.3);
  const std::vector<PolygonWithHoles> small =
      reachableOffsetParts(rooms, planningOptionsOf(parameters), in_the_small_room);
  ASSERT_EQ(small.size(), 1u);
  EXPECT_NEAR(area(small.front()), 1.0 * 2.0, 1e-9);
}

}  // namespace
}  // namespace kinematic_coverage::core
