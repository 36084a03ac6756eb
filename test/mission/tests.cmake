kc_add_gtest(test_mission
  test/mission/mission_file_reader_test.cpp
  test/mission/mission_file_writer_test.cpp
  test/mission/geojson_mission_reader_test.cpp
  test/mission/local_east_north_frame_test.cpp
  test/mission/mission_frame_test.cpp
  test/mission/utm_zone_frame_test.cpp
  test/mission/autopilot_mission_test.cpp
  test/mission/coverage_finding_test.cpp
  test/mission/coverage_safe_bars_test.cpp
  test/mission/polygon_sketch_test.cpp
  test/mission/pose_csv_reader_test.cpp
  test/mission/timed_tracking_consistency_test.cpp
  test/mission/wall_clearance_warning_test.cpp
  test/support/hard_map_generator.cpp
  LIBRARIES kc_mission kc_polygon_sketch kc_simulation)
# The UTM frame's test checks it against GeographicLib's own UTM coordinates.
target_include_directories(${PROJECT_NAME}_test_mission PRIVATE ${GeographicLib_INCLUDE_DIRS})
target_link_libraries(${PROJECT_NAME}_test_mission ${GeographicLib_LIBRARIES})
