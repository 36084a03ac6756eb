#pragma once

#include <geometry_msgs/PointStamped.h>
#include <std_msgs/Header.h>
#include <visualization_msgs/MarkerArray.h>

#include "coverage_system/planner/coverage_planner.h"
#include "kinematic_coverage/PolygonWithHolesStamped.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::nodes {

/// What coverage_planner computed, for rviz (`~markers`): the free area's hull and holes,
/// the offset free area and the parts of it not entered, the cells, the waypoint path with its
/// waypoints, and start and goal. Each group is its own namespace so that rviz can toggle it; every
/// marker of an earlier plan is deleted first, so a new plan replaces the old picture. Sizes grow
/// with the map and the points keep to MarkerScale::kPointBudget (rings through every k-th vertex,
/// at most a quarter of the budget in waypoint spheres) however large the chart.
visualization_msgs::MarkerArray planMarkers(const core::PolygonWithHoles& free_area,
                                            const core::CoveragePlan& plan,
                                            const core::Point2& start, const core::Point2& goal,
                                            const std_msgs::Header& header);

/// The inputs as coverage_planner received them, before any plan (`~markers`): the
/// polygon's rings and the start and goal known so far (null: not received), each in its
/// message's frame; every earlier marker is deleted first, as a new input makes the last
/// plan's picture stale.
visualization_msgs::MarkerArray inputMarkers(
    const kinematic_coverage::PolygonWithHolesStamped* polygon,
    const geometry_msgs::PointStamped* start, const geometry_msgs::PointStamped* goal);

/// A LINE_STRIP marker of a closed ring (the first point repeated at the end) through every
/// `stride`-th vertex.
visualization_msgs::Marker ringMarker(const core::Ring& ring, const std::string& ns, int id,
                                      const std_msgs::Header& header, float red, float green,
                                      float blue, double width, std::size_t stride = 1);

/// The marker that clears every marker rviz shows for the publisher (DELETEALL).
visualization_msgs::Marker deleteAllMarker(const std_msgs::Header& header);

}  // namespace kinematic_coverage::nodes
