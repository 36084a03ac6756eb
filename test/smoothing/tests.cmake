kc_add_gtest(test_smoothing
  test/smoothing/boundary_edge_index_test.cpp
  test/smoothing/bulb_turn_smoothing_test.cpp
  test/smoothing/corner_coverage_check_test.cpp
  test/smoothing/corner_smoothing_test.cpp
  test/smoothing/global_path_smoother_test.cpp
  test/smoothing/global_programme_brute_force_test.cpp
  test/smoothing/path_coverage_check_test.cpp
  test/smoothing/path_smoother_test.cpp
  test/smoothing/reverse_curve_smoothing_test.cpp
  test/smoothing/smoothing_strategy_properties_test.cpp
  LIBRARIES kc_parameters kc_smoothing)
