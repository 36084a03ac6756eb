kc_add_gtest(test_tool
  test/tool/coverage_tool_test.cpp
  test/tool/output_files_test.cpp
  test/tool/trajectory_csv_writer_test.cpp
  LIBRARIES kc_tool)
add_dependencies(test_tool coverage_tool)
