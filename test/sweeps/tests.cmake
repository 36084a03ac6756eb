kc_add_gtest(test_sweeps
  test/sweeps/frustum_sensor_test.cpp
  test/sweeps/sweep_pattern_test.cpp
  test/sweeps/coverage_raster_test.cpp
  test/sweeps/reachable_area_test.cpp
  test/sweeps/seen_area_test.cpp
  LIBRARIES kc_parameters kc_sweeps)
