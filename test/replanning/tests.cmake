kc_add_gtest(test_replanning
  test/replanning/raster_contours_test.cpp
  test/replanning/region_simplification_test.cpp
  test/replanning/remaining_area_test.cpp
  test/replanning/visited_history_test.cpp
  LIBRARIES kc_parameters kc_replanning kc_mission kc_trajectory)
# Resident memory of a 100 000-pose history (docs/REFERENCE.md, replanner).
kc_add_gtest(test_visited_history_memory
  test/replanning/visited_history_memory_test.cpp
  LIBRARIES kc_parameters kc_replanning)
