kc_add_stage_library(kc_sweeps
  SOURCES
    polygon_coverage_ros_bridge/sweeps/coverage_raster.cpp
    polygon_coverage_ros_bridge/sweeps/frustum_sensor.cpp
    polygon_coverage_ros_bridge/sweeps/reachable_area.cpp
    polygon_coverage_ros_bridge/sweeps/seen_area.cpp
    polygon_coverage_ros_bridge/sweeps/sweep_pattern.cpp
    polygon_coverage_ros_bridge/sweeps/waypoint_path_poses.cpp
  DEPENDS kc_geometry kc_decomposition)
# SeenArea marks long passes on every hardware thread.
target_link_libraries(kc_sweeps PUBLIC Threads::Threads)
