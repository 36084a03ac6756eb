kc_add_executable(coverage_benchmark bench/coverage/coverage_benchmark.cpp)
target_link_libraries(${PROJECT_NAME}_coverage_benchmark PRIVATE kc_mission kc_coverage kc_trajectory)
target_compile_definitions(${PROJECT_NAME}_coverage_benchmark PRIVATE
  KC_MISSIONS_DIR="${PROJECT_SOURCE_DIR}/config/missions")
