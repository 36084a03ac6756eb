kc_add_stage_library(kc_validation
  SOURCES
    polygon_coverage_ros_bridge/validation/polygon_validator.cpp
    polygon_coverage_ros_bridge/validation/polygon_cleaner.cpp
    polygon_coverage_ros_bridge/validation/free_area_builder.cpp
  DEPENDS kc_geometry
  CGAL)
