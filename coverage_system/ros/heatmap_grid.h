#pragma once

#include <nav_msgs/OccupancyGrid.h>
#include <std_msgs/Header.h>

#include <cstdint>
#include <vector>

#include "coverage_system/parameters/planner_parameters.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::nodes {

/// Cell values of the heatmap grid: kHeatmapStep per separate visit up to kHeatmapMaxVisits,
/// kHeatmapUnseen for a free cell never seen, -1 (unknown) outside the free area.
constexpr std::int8_t kHeatmapStep = 20;
constexpr int kHeatmapMaxVisits = 4;
constexpr std::int8_t kHeatmapUnseen = 100;

/// The coverage heatmap of a trajectory for rviz (the thesis's Fig. 4.2) as one image-like
/// grid, which rviz's Map display draws as a single texture however many cells it has:
/// a raster of at most `max_cells` cells over the free area, each cell's value from how
/// many separate times the footprint saw it (kHeatmapStep per visit, kHeatmapUnseen never
/// seen). A display aid: the figures of record come from coverage_tool's finer raster.
nav_msgs::OccupancyGrid heatmapGrid(const core::PolygonWithHoles& free_area,
                                    const std::vector<core::Pose2>& poses,
                                    const core::PlannerParameters& parameters,
                                    const std_msgs::Header& header, std::size_t max_cells = 250000);

}  // namespace kinematic_coverage::nodes
