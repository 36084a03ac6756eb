kc_add_gtest(test_smoothing
  test/smoothing/boundary_edge_index_test.cpp
  test/smoothing/corner_smoothing_test.cpp
  test/smoothing/path_smoother_test.cpp
  LIBRARIES kc_smoothing)

# Not a test: prints the smoothing time of a 10 000-waypoint boustrophedon path.
add_executable(smoothing_benchmark EXCLUDE_FROM_ALL test/smoothing/smoothing_benchmark.cpp)
target_link_libraries(smoothing_benchmark PRIVATE kc_smoothing)
