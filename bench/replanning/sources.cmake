kc_add_executable(replanning_benchmark bench/replanning/replanning_benchmark.cpp)
target_link_libraries(${PROJECT_NAME}_replanning_benchmark PRIVATE kc_replanning kc_mission kc_trajectory)
target_compile_definitions(${PROJECT_NAME}_replanning_benchmark PRIVATE KC_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
