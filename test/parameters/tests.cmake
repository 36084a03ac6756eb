kc_add_gtest(test_parameters
  test/parameters/parameter_schema_test.cpp
  test/parameters/stage_options_test.cpp
  LIBRARIES kc_parameters kc_smoothing kc_trajectory kc_simulation kc_replanning)
