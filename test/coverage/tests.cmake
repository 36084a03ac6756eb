kc_add_gtest(test_coverage
  test/coverage/coverage_raster_test.cpp
  test/coverage/reachable_area_test.cpp
  test/coverage/seen_area_test.cpp
  test/coverage/coverage_evaluator_test.cpp
  test/coverage/analytic_coverage_test.cpp
  LIBRARIES kc_coverage)
