kc_add_gtest(test_sweeps
  test/sweeps/frustum_sensor_test.cpp
  test/sweeps/sweep_pattern_test.cpp
  LIBRARIES kc_sweeps)
