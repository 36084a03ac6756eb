#include "coverage_system/ros/heatmap_grid.h"

#include <algorithm>

#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/sweeps/coverage_raster.h"
#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"
#include "polygon_coverage_ros_bridge/sweeps/seen_area.h"

namespace kinematic_coverage::nodes {

nav_msgs::OccupancyGrid heatmapGrid(const core::PolygonWithHoles& free_area,
                                    const std::vector<core::Pose2>& poses,
                                    const core::PlannerParameters& parameters,
                                    const std_msgs::Header& header, std::size_t max_cells) {
  core::RasterResolution resolution;
  resolution.max_cells = max_cells;
  const core::CoverageRaster raster = core::CoverageRaster::covering(free_area, resolution);
  core::SeenArea seen(raster);
  seen.addTrajectory(poses, core::sensorOf(parameters));
  const core::CellMask free = raster.rasterize(free_area);

  nav_msgs::OccupancyGrid grid;
  grid.header = header;
  grid.info.map_load_time = header.stamp;
  grid.info.resolution = static_cast<float>(raster.cellSize());
  grid.info.width = static_cast<std::uint32_t>(raster.columns());
  grid.info.height = static_cast<std::uint32_t>(raster.rows());
  grid.info.origin.position.x = raster.origin().x();
  grid.info.origin.position.y = raster.origin().y();
  grid.info.origin.position.z = -0.05;  // under the paths
  grid.info.origin.orientation.w = 1.0;
  // Row-major from the origin, as the raster's index(row, column).
  grid.data.assign(raster.cellCount(), -1);
  for (std::size_t index = 0; index < free.size(); ++index) {
    if (free[index] == 0) continue;
    const int visits = std::min<int>(seen.visits(index), kHeatmapMaxVisits);
    grid.data[index] =
        visits == 0 ? kHeatmapUnseen : static_cast<std::int8_t>(kHeatmapStep * visits);
  }
  return grid;
}

}  // namespace kinematic_coverage::nodes
