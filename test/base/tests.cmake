# base/ is header-only; kc_route, which runs parallelFor, brings its include path and threads.
kc_add_gtest(test_base
  test/base/indexed_min_heap_test.cpp
  test/base/number_format_test.cpp
  test/base/parallel_for_test.cpp
  test/base/huge_page_heap_test.cpp
  LIBRARIES kc_route)
# The program whose restart huge_page_heap_test watches: a test's helper, never installed
# ("test" in its name tells catkin_lint so).
add_executable(${PROJECT_NAME}_test_huge_page_heap_probe EXCLUDE_FROM_ALL
  test/base/huge_page_heap_probe.cpp)
target_include_directories(${PROJECT_NAME}_test_huge_page_heap_probe PRIVATE ${PROJECT_SOURCE_DIR})
add_dependencies(${PROJECT_NAME}_test_base ${PROJECT_NAME}_test_huge_page_heap_probe)
target_compile_definitions(${PROJECT_NAME}_test_base PRIVATE
  KC_HUGE_PAGE_PROBE_PATH="$<TARGET_FILE:${PROJECT_NAME}_test_huge_page_heap_probe>")
