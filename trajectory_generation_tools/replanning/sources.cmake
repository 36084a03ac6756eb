kc_add_stage_library(kc_replanning
  SOURCES
    trajectory_generation_tools/replanning/alpha_shape_triangles.cpp
    trajectory_generation_tools/replanning/raster_contours.cpp
    trajectory_generation_tools/replanning/region_simplification.cpp
    trajectory_generation_tools/replanning/remaining_area.cpp
    trajectory_generation_tools/replanning/visited_history.cpp
  DEPENDS kc_geometry kc_validation kc_sweeps
  CGAL)
