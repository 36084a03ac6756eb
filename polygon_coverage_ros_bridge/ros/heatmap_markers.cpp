#include "polygon_coverage_ros_bridge/ros/heatmap_markers.h"

#include "polygon_coverage_ros_bridge/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/sweeps/coverage_raster.h"
#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"
#include "polygon_coverage_ros_bridge/sweeps/seen_area.h"
#include "trajectory_generation_tools/plot/coverage_plot.h"

namespace kinematic_coverage::nodes {

visualization_msgs::Marker heatmapMarker(const core::PolygonWithHoles& free_area,
                                         const std::vector<core::Pose2>& poses,
                                         const core::PlannerParameters& parameters,
                                         const std_msgs::Header& header, std::size_t max_cells) {
  core::RasterResolution resolution;
  resolution.max_cells = max_cells;
  const core::CoverageRaster raster = core::CoverageRaster::covering(free_area, resolution);
  core::SeenArea seen(raster);
  seen.addTrajectory(poses, core::sensorOf(parameters));
  const core::CellMask free = raster.rasterize(free_area);

  visualization_msgs::Marker marker;
  marker.header = header;
  marker.ns = "coverage_heatmap";
  marker.id = 0;
  marker.type = visualization_msgs::Marker::CUBE_LIST;
  marker.action = visualization_msgs::Marker::ADD;
  marker.pose.orientation.w = 1.0;
  marker.pose.position.z = -0.05;  // under the paths
  marker.scale.x = marker.scale.y = raster.cellSize();
  marker.scale.z = 0.01;
  for (std::size_t index = 0; index < free.size(); ++index) {
    if (free[index] == 0) continue;
    const core::Point2 centre = raster.cellCentre(index);
    geometry_msgs::Point point;
    point.x = centre.x();
    point.y = centre.y();
    marker.points.push_back(point);
    const core::PlotColour colour = core::CoveragePlot::visitColour(seen.visits(index));
    std_msgs::ColorRGBA rgba;
    rgba.r = colour.red / 255.0f;
    rgba.g = colour.green / 255.0f;
    rgba.b = colour.blue / 255.0f;
    rgba.a = 0.6f;
    marker.colors.push_back(rgba);
  }
  return marker;
}

}  // namespace kinematic_coverage::nodes
