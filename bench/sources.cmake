# Benchmark programs: each prints a table; figures and commands in docs/BENCHMARKS.md.
include(bench/coverage/sources.cmake OPTIONAL)
include(bench/gtsp/sources.cmake OPTIONAL)
include(bench/planner/sources.cmake OPTIONAL)
include(bench/replanning/sources.cmake OPTIONAL)
include(bench/simulation/sources.cmake OPTIONAL)
include(bench/smoothing/sources.cmake OPTIONAL)
include(bench/soak/sources.cmake OPTIONAL)
include(bench/trajectory/sources.cmake OPTIONAL)

# Smoke runs: each benchmark for a few seconds under ctest, so that a benchmark that stops
# building or running fails CI. Their figures are checked against docs/ by doc_figures.
# Tests, so left out with testing off (as the root CMakeLists.txt leaves test/ out).
if(catkin_FOUND AND NOT CATKIN_ENABLE_TESTING)
  return()
endif()
function(kc_add_benchmark_smoke target)
  add_test(NAME smoke_${target} COMMAND ${PROJECT_NAME}_${target} ${ARGN})
  set_tests_properties(smoke_${target} PROPERTIES TIMEOUT 300)
endfunction()
kc_add_benchmark_smoke(coverage_benchmark --runs 1)
kc_add_benchmark_smoke(hard_map_writer --out ${CMAKE_BINARY_DIR}/hard_maps --seeds 0:1)
kc_add_benchmark_smoke(gtsp_benchmark --seeds 1 --instances 11eil51,4br17,20kroA100)
kc_add_benchmark_smoke(planner_peer_benchmark --runs 1)
kc_add_benchmark_smoke(scaling_benchmark --sizes 500:10 --plot ${CMAKE_BINARY_DIR}/scaling.png)
kc_add_benchmark_smoke(lake_survey_benchmark --areas 20)
# The time cost of the first shorelines, the lakes, the shipped missions and the peer's
# polygons against the values recorded when coverage came to be measured on the exact offset
# (at most 1.005 times each).
add_test(NAME planner_reference_check COMMAND ${PROJECT_NAME}_planner_reference --runs 1 --shorelines 3
  --compare ${PROJECT_SOURCE_DIR}/bench/data/planner_reference_exact_offset.csv)
set_tests_properties(planner_reference_check PROPERTIES TIMEOUT 600)
kc_add_benchmark_smoke(large_hull_benchmark 300)
kc_add_benchmark_smoke(memory_bound_benchmark --holes 3 --vertices 200)
kc_add_benchmark_smoke(replanning_benchmark --runs 1)
kc_add_benchmark_smoke(smoothing_comparison --only lake_7_5)
kc_add_benchmark_smoke(soak_test --seeds 0:4 --trajectory-coverage)
kc_add_benchmark_smoke(family_soak --maps 1 --families comb,rooms --oracle-max-vertices 0)
kc_add_benchmark_smoke(trajectory_benchmark --runs 1)
kc_add_benchmark_smoke(strategy_benchmark --maps 1 --families comb,rooms --lakes 1)
kc_add_benchmark_smoke(repair_benchmark --maps 1 --families comb,rooms)
