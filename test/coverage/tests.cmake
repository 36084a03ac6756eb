kc_add_gtest(test_coverage
  test/coverage/coverage_evaluator_test.cpp
  test/coverage/analytic_coverage_test.cpp
  # The exact polygon oracle (CGAL) and its agreement with the raster on planned maps.
  test/coverage/exact_coverage_oracle.cpp
  test/coverage/coverage_oracle_test.cpp
  LIBRARIES kc_parameters kc_coverage kc_mission kc_trajectory CGAL::CGAL)
