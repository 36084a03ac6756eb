kc_add_stage_library(kc_geometry
  SOURCES
    polygon_coverage_ros_bridge/geometry/planar_geometry.cpp)
