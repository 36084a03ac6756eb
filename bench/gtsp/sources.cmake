# GTSPLIB benchmark of the GTSP solver; figures in docs/BENCHMARKS.md.
add_executable(gtsp_benchmark bench/gtsp/gtsp_benchmark.cpp)
target_link_libraries(gtsp_benchmark PRIVATE kc_gtsp)
target_compile_definitions(gtsp_benchmark PRIVATE
  KC_GTSPLIB_DIR="${PROJECT_SOURCE_DIR}/bench/data/gtsplib")
