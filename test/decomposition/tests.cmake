kc_add_gtest(test_decomposition
  test/decomposition/sweep_direction_test.cpp
  test/decomposition/sweep_line_decomposition_test.cpp
  test/decomposition/best_decomposition_test.cpp
  LIBRARIES kc_decomposition)
