kc_add_stage_library(kc_coverage
  SOURCES
    trajectory_generation_tools/coverage/coverage_evaluator.cpp
  DEPENDS kc_geometry kc_sweeps)
