kc_add_gtest(test_geometry
  test/geometry/boundary_simplification_test.cpp
  test/geometry/planar_geometry_test.cpp
  test/geometry/wall_offset_test.cpp
  test/geometry/edge_grid_test.cpp
  test/geometry/nearest_segment_index_test.cpp
  test/geometry/region_intersection_test.cpp
  test/support/hard_map_generator.cpp
  LIBRARIES kc_geometry kc_validation kc_parameters)
