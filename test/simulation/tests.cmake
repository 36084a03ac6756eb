kc_add_gtest(test_simulation
  test/simulation/driven_path_clearance_test.cpp
  test/simulation/environment_disturbance_test.cpp
  test/simulation/gauss_markov_process_test.cpp
  test/simulation/line_of_sight_guidance_test.cpp
  test/simulation/path_distance_test.cpp
  test/simulation/planar_rigid_body_test.cpp
  test/simulation/robot_model_warnings_test.cpp
  test/simulation/robot_simulator_test.cpp
  test/simulation/standard_normal_source_test.cpp
  test/simulation/tracking_error_statistics_test.cpp
  test/simulation/pose_sequence_timing_test.cpp
  test/simulation/timed_reference_test.cpp
  test/simulation/trajectory_follower_test.cpp
  test/simulation/vectored_thrust_allocation_test.cpp
  test/simulation/actual_path_plot_test.cpp
  LIBRARIES kc_parameters kc_simulation kc_plot PkgConfig::CAIRO)

