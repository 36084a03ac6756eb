kc_add_executable(smoothing_comparison bench/smoothing/smoothing_comparison.cpp)
target_link_libraries(${PROJECT_NAME}_smoothing_comparison PRIVATE kc_mission kc_planner kc_trajectory kc_coverage)
target_compile_definitions(${PROJECT_NAME}_smoothing_comparison PRIVATE
  KC_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
  KC_PEER_POLYGONS_DIR="${PROJECT_SOURCE_DIR}/bench/data/pcp_polygons")

# The smoothing strategies over the hard-map families and the lake maps.
kc_add_executable(strategy_benchmark bench/smoothing/strategy_benchmark.cpp
  test/support/hard_map_generator.cpp test/support/lake_map_generator.cpp)
target_link_libraries(${PROJECT_NAME}_strategy_benchmark PRIVATE kc_tool kc_mission kc_planner kc_trajectory kc_coverage)
target_compile_definitions(${PROJECT_NAME}_strategy_benchmark PRIVATE KC_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
