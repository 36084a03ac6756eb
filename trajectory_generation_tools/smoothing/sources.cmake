kc_add_stage_library(kc_smoothing
  SOURCES
    trajectory_generation_tools/smoothing/boundary_edge_index.cpp
    trajectory_generation_tools/smoothing/corner_geometry.cpp
    trajectory_generation_tools/smoothing/corner_smoother.cpp
    trajectory_generation_tools/smoothing/inner_smoothing.cpp
    trajectory_generation_tools/smoothing/outer_arc_chain.cpp
    trajectory_generation_tools/smoothing/outer_smoothing_bisector.cpp
    trajectory_generation_tools/smoothing/outer_smoothing_tangent.cpp
    trajectory_generation_tools/smoothing/path_smoother.cpp
    trajectory_generation_tools/smoothing/smoothing_feasibility.cpp
  DEPENDS kc_path kc_geometry
  CGAL)
