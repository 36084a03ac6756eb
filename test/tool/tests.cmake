kc_add_gtest(test_tool
  test/tool/coverage_tool_test.cpp
  test/tool/output_files_test.cpp
  test/tool/trajectory_csv_writer_test.cpp
  LIBRARIES kc_tool)
add_dependencies(${PROJECT_NAME}_test_tool ${PROJECT_NAME}_coverage_tool)
