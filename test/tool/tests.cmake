kc_add_gtest(test_tool
  test/tool/autopilot_mission_writer_test.cpp
  test/tool/coverage_tool_test.cpp
  test/tool/output_files_test.cpp
  test/tool/trajectory_csv_writer_test.cpp
  LIBRARIES kc_tool)
add_dependencies(${PROJECT_NAME}_test_tool ${PROJECT_NAME}_coverage_tool)
# The vehicle's mission files read back with Python's json module and as the QGC WPL text.
find_package(Python3 REQUIRED COMPONENTS Interpreter)
add_test(NAME autopilot_mission_files COMMAND ${Python3_EXECUTABLE}
  ${PROJECT_SOURCE_DIR}/test/tool/autopilot_mission_files_test.py
  $<TARGET_FILE:${PROJECT_NAME}_coverage_tool>)
