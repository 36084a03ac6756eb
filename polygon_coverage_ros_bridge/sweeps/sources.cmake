kc_add_stage_library(kc_sweeps
  SOURCES
    polygon_coverage_ros_bridge/sweeps/frustum_sensor.cpp
  DEPENDS kc_geometry)
