add_executable(soak_test bench/soak/soak_test.cpp)
target_link_libraries(soak_test PRIVATE kc_planner kc_coverage kc_trajectory)
