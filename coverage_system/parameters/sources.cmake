kc_add_stage_library(kc_parameters
  SOURCES
    coverage_system/parameters/parameter_schema.cpp
    coverage_system/parameters/stage_options.cpp
  DEPENDS kc_geometry kc_decomposition kc_sweeps kc_route kc_smoothing kc_trajectory kc_simulation
    kc_replanning)
