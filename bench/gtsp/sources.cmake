# GTSPLIB benchmark of the GTSP solver; figures in docs/BENCHMARKS.md.
kc_add_executable(gtsp_benchmark bench/gtsp/gtsp_benchmark.cpp)
target_link_libraries(${PROJECT_NAME}_gtsp_benchmark PRIVATE kc_gtsp)
target_compile_definitions(${PROJECT_NAME}_gtsp_benchmark PRIVATE
  KC_GTSPLIB_DIR="${PROJECT_SOURCE_DIR}/bench/data/gtsplib")
