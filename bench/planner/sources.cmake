kc_add_executable(planner_peer_benchmark bench/planner/planner_peer_benchmark.cpp)
target_link_libraries(${PROJECT_NAME}_planner_peer_benchmark PRIVATE kc_planner kc_mission kc_validation kc_coverage)
target_compile_definitions(${PROJECT_NAME}_planner_peer_benchmark PRIVATE
  KC_PEER_POLYGONS_DIR="${PROJECT_SOURCE_DIR}/bench/data/pcp_polygons")

kc_add_executable(large_hull_benchmark bench/planner/large_hull_benchmark.cpp)
target_link_libraries(${PROJECT_NAME}_large_hull_benchmark PRIVATE kc_planner)

kc_add_executable(memory_bound_benchmark bench/planner/memory_bound_benchmark.cpp)
target_link_libraries(${PROJECT_NAME}_memory_bound_benchmark PRIVATE kc_mission kc_planner kc_trajectory)

# coverage_repair off and on over the hard-map families.
kc_add_executable(repair_benchmark bench/planner/repair_benchmark.cpp
  test/support/hard_map_generator.cpp)
target_link_libraries(${PROJECT_NAME}_repair_benchmark PRIVATE kc_mission kc_planner kc_coverage)

# The time cost and planning time of the maps that plan before the shoreline-scaling work,
# recorded in bench/data/planner_reference.csv.
kc_add_executable(planner_reference bench/planner/planner_reference.cpp
  test/support/hard_map_generator.cpp test/support/lake_map_generator.cpp)
target_link_libraries(${PROJECT_NAME}_planner_reference PRIVATE kc_mission kc_planner)
target_compile_definitions(${PROJECT_NAME}_planner_reference PRIVATE KC_SOURCE_DIR="${PROJECT_SOURCE_DIR}")

# Planning time and peak memory against the size of a lake chart (coverage_tool plan in a
# child process per map).
kc_add_executable(scaling_benchmark bench/planner/scaling_benchmark.cpp
  bench/support/coverage_tool_run.cpp bench/support/log_log_plot.cpp
  test/support/hard_map_generator.cpp)
target_link_libraries(${PROJECT_NAME}_scaling_benchmark PRIVATE kc_validation kc_geometry kc_parameters
  PkgConfig::CAIRO)
add_dependencies(${PROJECT_NAME}_scaling_benchmark ${PROJECT_NAME}_coverage_tool)

# Whole lakes of 20 to 500 km^2 from GeoJSON, as an operator plans them (coverage_tool plan
# in a child process per lake).
kc_add_executable(lake_survey_benchmark bench/planner/lake_survey_benchmark.cpp
  bench/support/coverage_tool_run.cpp test/support/hard_map_generator.cpp
  test/support/survey_lake_generator.cpp)
target_link_libraries(${PROJECT_NAME}_lake_survey_benchmark PRIVATE kc_tool kc_mission)
add_dependencies(${PROJECT_NAME}_lake_survey_benchmark ${PROJECT_NAME}_coverage_tool)
