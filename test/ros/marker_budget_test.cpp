#include <gtest/gtest.h>

#include "coverage_system/mission/mission_file_reader.h"
#include "coverage_system/mission/mission_planner.h"
#include "coverage_system/mission/trajectory_pipeline.h"
#include "coverage_system/ros/heatmap_grid.h"
#include "coverage_system/ros/marker_scale.h"
#include "coverage_system/ros/plan_markers.h"
#include "coverage_system/ros/trajectory_markers.h"
#include "test/support/survey_lake_generator.h"

namespace kinematic_coverage::nodes {
namespace {

/// What coverage_planner and smooth_trajectory_generator publish for rviz of a mission.
struct Published {
  visualization_msgs::MarkerArray plan;
  visualization_msgs::MarkerArray trajectory;
  nav_msgs::OccupancyGrid heatmap;
  std::size_t ring_vertices = 0;  ///< of the free area, offset parts and cells
};

Published publish(const core::Mission& mission) {
  const core::PlannedMission planned = core::planMission(mission);
  std_msgs::Header header;
  header.frame_id = "map";
  Published published;
  published.plan =
      planMarkers(planned.free_area, planned.plan, mission.start, mission.goal, header);
  const core::MeasuredTrajectory measured =
      core::TrajectoryPipeline(mission.parameters, planned.plan.exact_offset_parts)
          .run(planned.plan.waypoints, planned.free_area);
  published.trajectory = trajectoryMarkers(measured.trajectory.path, header);
  published.heatmap = heatmapGrid(planned.free_area, measured.poses, mission.parameters, header);
  return published;
}

TEST(MarkerBudget, A500SquareKilometreLakeKeepsToTheBudgets) {
  const core::Mission lake = core::testing::SurveyLakeGenerator().generate(0, 500.0);
  const Published published = publish(lake);
  const std::size_t plan_points = MarkerScale::pointCount(published.plan);
  const std::size_t trajectory_points = MarkerScale::pointCount(published.trajectory);
  RecordProperty("plan_marker_points", static_cast<int>(plan_points));
  RecordProperty("trajectory_marker_points", static_cast<int>(trajectory_points));
  RecordProperty("heatmap_cells",
                 static_cast<int>(published.heatmap.info.width * published.heatmap.info.height));
  EXPECT_LE(plan_points, MarkerScale::kPointBudget);
  EXPECT_LE(trajectory_points, MarkerScale::kPointBudget);
  EXPECT_LT(plan_points + trajectory_points, 20000u);
  EXPECT_LE(static_cast<std::size_t>(published.heatmap.info.width) * published.heatmap.info.height,
            250000u);
  // Lines as wide as a lake shown whole needs: the hull's line is tens of metres wide.
  ASSERT_GT(published.plan.markers.size(), 1u);
  EXPECT_GT(published.plan.markers[1].scale.x, 10.0);
  // Every marker still draws something.
  for (const visualization_msgs::Marker& marker : published.trajectory.markers) {
    if (marker.action == visualization_msgs::Marker::ADD) EXPECT_FALSE(marker.points.empty());
  }
}

TEST(MarkerBudget, TheLakeMissionKeepsEveryVertexAndItsSizes) {
  const core::Mission lake = core::MissionFileReader().read(std::string(KC_SOURCE_DIR) +
                                                            "/config/missions/lake_30x30.yaml");
  const Published published = publish(lake);
  // The hull: its 4 corners and the closing one; the base line width.
  ASSERT_GT(published.plan.markers.size(), 1u);
  const visualization_msgs::Marker& hull = published.plan.markers[1];
  EXPECT_EQ(hull.ns, "polygon");
  EXPECT_EQ(hull.points.size(), 5u);
  EXPECT_DOUBLE_EQ(hull.scale.x, 0.1);
  // Arcs as chords of at most 0.1 rad: a quarter turn of 1 m radius is 16 chords.
  std::size_t arc_points = 0;
  for (const visualization_msgs::Marker& marker : published.trajectory.markers) {
    if (marker.ns.rfind("arcs_", 0) == 0) arc_points += marker.points.size();
  }
  EXPECT_GT(arc_points, 200u);
  EXPECT_LT(MarkerScale::pointCount(published.plan), MarkerScale::kPointBudget / 10);
}

TEST(MarkerBudget, StrideKeepsRingsWithinTheBudget) {
  EXPECT_EQ(MarkerScale::stride(500, 10000), 1u);
  EXPECT_EQ(MarkerScale::stride(10000, 10000), 1u);
  EXPECT_EQ(MarkerScale::stride(10001, 10000), 2u);
  EXPECT_EQ(MarkerScale::stride(35000, 10000), 4u);
  EXPECT_EQ(MarkerScale::stride(7, 0), 7u);
}

}  // namespace
}  // namespace kinematic_coverage::nodes
