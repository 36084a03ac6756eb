kc_add_gtest(test_replanning
  test/replanning/raster_contours_test.cpp
  test/replanning/region_simplification_test.cpp
  test/replanning/remaining_area_test.cpp
  test/replanning/replanner_test.cpp
  LIBRARIES kc_replanning kc_mission kc_trajectory)
