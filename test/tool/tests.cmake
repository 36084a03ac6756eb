kc_add_gtest(test_tool
  test/tool/coverage_tool_test.cpp)
add_dependencies(test_tool coverage_tool)
