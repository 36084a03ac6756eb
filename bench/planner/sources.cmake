add_executable(planner_peer_benchmark bench/planner/planner_peer_benchmark.cpp)
target_link_libraries(planner_peer_benchmark PRIVATE kc_planner kc_mission kc_validation kc_coverage)
target_compile_definitions(planner_peer_benchmark PRIVATE
  KC_PEER_POLYGONS_DIR="${PROJECT_SOURCE_DIR}/../shared/benchmarks/pcp_polygons")

add_executable(large_hull_benchmark bench/planner/large_hull_benchmark.cpp)
target_link_libraries(large_hull_benchmark PRIVATE kc_planner)
