add_executable(soak_test bench/soak/soak_test.cpp)
target_link_libraries(soak_test PRIVATE kc_planner kc_coverage kc_trajectory)

add_executable(hard_map_writer bench/soak/hard_map_writer.cpp test/support/hard_map_generator.cpp)
target_link_libraries(hard_map_writer PRIVATE kc_validation kc_geometry)

# The hard-map families through planMission, checked against the exact coverage oracle.
add_executable(family_soak bench/soak/family_soak.cpp test/support/hard_map_generator.cpp
  test/coverage/exact_coverage_oracle.cpp)
target_link_libraries(family_soak PRIVATE kc_mission kc_planner kc_coverage kc_trajectory
  CGAL::CGAL)
