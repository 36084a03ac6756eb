add_executable(smoothing_comparison bench/smoothing/smoothing_comparison.cpp)
target_link_libraries(smoothing_comparison PRIVATE kc_mission kc_planner kc_trajectory kc_coverage)
target_compile_definitions(smoothing_comparison PRIVATE
  KC_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
  KC_PEER_POLYGONS_DIR="${PROJECT_SOURCE_DIR}/bench/data/pcp_polygons")
