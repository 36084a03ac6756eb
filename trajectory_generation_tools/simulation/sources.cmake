kc_add_stage_library(kc_simulation
  SOURCES
    trajectory_generation_tools/simulation/driven_path_clearance.cpp
    trajectory_generation_tools/simulation/environment_disturbance.cpp
    trajectory_generation_tools/simulation/gauss_markov_process.cpp
    trajectory_generation_tools/simulation/line_of_sight_guidance.cpp
    trajectory_generation_tools/simulation/path_distance.cpp
    trajectory_generation_tools/simulation/planar_rigid_body.cpp
    trajectory_generation_tools/simulation/pose_sequence_timing.cpp
    trajectory_generation_tools/simulation/robot_model_warnings.cpp
    trajectory_generation_tools/simulation/robot_simulator.cpp
    trajectory_generation_tools/simulation/standard_normal_source.cpp
    trajectory_generation_tools/simulation/timed_reference.cpp
    trajectory_generation_tools/simulation/tracking_error_statistics.cpp
    trajectory_generation_tools/simulation/trajectory_follower.cpp
    trajectory_generation_tools/simulation/vectored_thrust_allocation.cpp
  DEPENDS kc_geometry)
