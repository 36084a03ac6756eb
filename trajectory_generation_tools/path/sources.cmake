kc_add_stage_library(kc_path
  SOURCES
    trajectory_generation_tools/path/path_primitive.cpp
  DEPENDS kc_geometry)
