#pragma once

#include <std_msgs/Header.h>
#include <visualization_msgs/Marker.h>

#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "polygon_coverage_ros_bridge/parameters/planner_parameters.h"

namespace kinematic_coverage::nodes {

/// The coverage heatmap of a trajectory for rviz (the thesis's
/// Fig. 4.2): one flat square per cell of the free area on a raster of at most
/// `max_cells` cells, coloured as plot.png colours separate visits (red: never seen). A
/// display aid: the figures of record come from coverage_tool's finer raster.
visualization_msgs::Marker heatmapMarker(const core::PolygonWithHoles& free_area,
                                         const std::vector<core::Pose2>& poses,
                                         const core::PlannerParameters& parameters,
                                         const std_msgs::Header& header,
                                         std::size_t max_cells = 40000);

}  // namespace kinematic_coverage::nodes
