kc_add_stage_library(kc_parameters
  SOURCES
    polygon_coverage_ros_bridge/parameters/parameter_schema.cpp
    polygon_coverage_ros_bridge/parameters/stage_options.cpp
  DEPENDS kc_geometry kc_decomposition kc_sweeps kc_route kc_smoothing kc_trajectory kc_simulation
    kc_replanning)
