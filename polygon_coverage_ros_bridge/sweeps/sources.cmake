kc_add_stage_library(kc_sweeps
  SOURCES
    polygon_coverage_ros_bridge/sweeps/frustum_sensor.cpp
    polygon_coverage_ros_bridge/sweeps/sweep_pattern.cpp
  DEPENDS kc_geometry kc_decomposition)
