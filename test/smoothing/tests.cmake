kc_add_gtest(test_smoothing
  test/smoothing/boundary_edge_index_test.cpp
  test/smoothing/corner_smoothing_test.cpp
  test/smoothing/path_smoother_test.cpp
  LIBRARIES kc_smoothing)
