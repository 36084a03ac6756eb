kc_add_stage_library(kc_smoothing
  SOURCES
    trajectory_generation_tools/smoothing/boundary_edge_index.cpp
    trajectory_generation_tools/smoothing/corner_geometry.cpp
    trajectory_generation_tools/smoothing/corner_coverage_check.cpp
    trajectory_generation_tools/smoothing/corner_smoother.cpp
    trajectory_generation_tools/smoothing/corner_waypoints.cpp
    trajectory_generation_tools/smoothing/global_path_smoother.cpp
    trajectory_generation_tools/smoothing/inner_smoothing.cpp
    trajectory_generation_tools/smoothing/outer_arc_chain.cpp
    trajectory_generation_tools/smoothing/outer_smoothing_bisector.cpp
    trajectory_generation_tools/smoothing/outer_smoothing_tangent.cpp
    trajectory_generation_tools/smoothing/path_smoother.cpp
    trajectory_generation_tools/smoothing/reverse_curve_smoothing.cpp
    trajectory_generation_tools/smoothing/smoothed_path_assembler.cpp
    trajectory_generation_tools/smoothing/smoothing_feasibility.cpp
  DEPENDS kc_path kc_geometry kc_sweeps kc_coverage
  CGAL)
