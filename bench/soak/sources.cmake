kc_add_executable(soak_test bench/soak/soak_test.cpp)
target_link_libraries(${PROJECT_NAME}_soak_test PRIVATE kc_mission kc_planner kc_coverage kc_trajectory)

kc_add_executable(hard_map_writer bench/soak/hard_map_writer.cpp test/support/hard_map_generator.cpp)
target_link_libraries(${PROJECT_NAME}_hard_map_writer PRIVATE kc_validation kc_geometry kc_parameters)

# The hard-map families through planMission, checked against the exact coverage oracle.
kc_add_executable(family_soak bench/soak/family_soak.cpp test/support/hard_map_generator.cpp
  test/coverage/exact_coverage_oracle.cpp)
target_link_libraries(${PROJECT_NAME}_family_soak PRIVATE kc_mission kc_planner kc_coverage kc_trajectory
  CGAL::CGAL)
