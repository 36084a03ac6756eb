kc_add_gtest(test_route
  test/route/segment_cost_test.cpp
  test/route/boundary_grid_test.cpp
  test/route/visibility_graph_test.cpp
  test/route/jog_removal_test.cpp
  test/route/offset_part_joiner_test.cpp
  LIBRARIES kc_parameters kc_route)
