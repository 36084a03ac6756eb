kc_add_stage_library(kc_validation
  SOURCES
    polygon_coverage_ros_bridge/validation/parameter_validator.cpp
    polygon_coverage_ros_bridge/validation/polygon_validator.cpp
    polygon_coverage_ros_bridge/validation/polygon_cleaner.cpp
  DEPENDS kc_geometry
  CGAL)
