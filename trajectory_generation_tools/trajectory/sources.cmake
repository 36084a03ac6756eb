kc_add_stage_library(kc_trajectory
  SOURCES
    trajectory_generation_tools/trajectory/continuous_curvature_turn.cpp
    trajectory_generation_tools/trajectory/continuous_curvature_turns.cpp
    trajectory_generation_tools/trajectory/primitive_distance.cpp
    trajectory_generation_tools/trajectory/primitive_path_metrics.cpp
    trajectory_generation_tools/trajectory/primitive_path_validation.cpp
    trajectory_generation_tools/trajectory/segment_path_builder.cpp
    trajectory_generation_tools/trajectory/trajectory_generator.cpp
    trajectory_generation_tools/trajectory/trajectory_sampler.cpp
    trajectory_generation_tools/trajectory/trajectory_thinning.cpp
    trajectory_generation_tools/trajectory/trajectory_timing.cpp
  DEPENDS kc_smoothing kc_path kc_geometry)
