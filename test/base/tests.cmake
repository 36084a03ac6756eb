# base/ is header-only; kc_route, which runs parallelFor, brings its include path and threads.
kc_add_gtest(test_base
  test/base/indexed_min_heap_test.cpp
  test/base/number_format_test.cpp
  test/base/parallel_for_test.cpp
  LIBRARIES kc_route)
