kc_add_stage_library(kc_coverage
  SOURCES
    trajectory_generation_tools/coverage/coverage_evaluator.cpp
    trajectory_generation_tools/coverage/coverage_raster.cpp
    trajectory_generation_tools/coverage/reachable_area.cpp
    trajectory_generation_tools/coverage/seen_area.cpp
    trajectory_generation_tools/coverage/waypoint_path_poses.cpp
  DEPENDS kc_geometry kc_sweeps)
