kc_add_gtest(test_trajectory
  test/trajectory/continuous_curvature_turn_test.cpp
  test/trajectory/continuous_curvature_turns_test.cpp
  test/trajectory/primitive_path_metrics_test.cpp
  test/trajectory/segment_path_builder_test.cpp
  test/trajectory/trajectory_generator_test.cpp
  test/trajectory/trajectory_sampler_test.cpp
  test/trajectory/trajectory_thinning_test.cpp
  test/trajectory/trajectory_timing_test.cpp
  LIBRARIES kc_parameters kc_trajectory)
