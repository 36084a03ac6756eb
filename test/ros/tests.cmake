# rostests of the nodes (catkin builds only): whole flows against running nodes.
if(catkin_FOUND)
  find_package(rostest REQUIRED)
  # The markers and heatmap grid the nodes publish for rviz, at lake scale (no running nodes).
  kc_add_gtest(test_ros_markers test/ros/marker_budget_test.cpp
    test/support/hard_map_generator.cpp test/support/survey_lake_generator.cpp
    LIBRARIES kc_ros_bridge kc_mission)
  add_rostest(test/ros/pipeline_lake.test DEPENDENCIES ${KC_NODE_TARGETS})
  add_rostest(test/ros/planner_requests.test DEPENDENCIES ${KC_NODE_TARGETS})
  # Load: 100 polygons a second for 10 s to coverage_planner with plan_on_receive.
  add_rostest(test/ros/planner_load.test DEPENDENCIES ${KC_NODE_TARGETS})
  add_rostest(test/ros/replanning.test DEPENDENCIES ${KC_NODE_TARGETS})
  add_rostest(test/ros/auv_simulator.test DEPENDENCIES ${KC_NODE_TARGETS})
  # Bad messages and wrongly typed parameters: one ROS_ERROR, a failed status, no output.
  add_rostest(test/ros/bad_messages.test DEPENDENCIES ${KC_NODE_TARGETS})
  add_rostest(test/ros/node_parameters.test DEPENDENCIES ${KC_NODE_TARGETS})
  # Area left unseen: a ROS_WARN and the warning in ~status.
  add_rostest(test/ros/unseen_area.test DEPENDENCIES ${KC_NODE_TARGETS})
  # The replanner's resident memory over 100 000 visited poses.
  add_rostest(test/ros/replanner_memory.test DEPENDENCIES ${KC_NODE_TARGETS})
  # GUI tests of the rviz tools: need a DISPLAY (xvfb-run). Registered as add_rostest
  # does, through gui_rostest.sh, which without a DISPLAY writes the result as skipped and
  # exits 77: ctest reports it skipped, catkin_test_results counts it skipped.
  find_program(KINEMATIC_COVERAGE_ROSTEST rostest)
  if(NOT KINEMATIC_COVERAGE_ROSTEST)
    message(FATAL_ERROR "rostest not found: source your ROS setup or run "
      "scripts/install_dependencies.sh")
  endif()
  function(kc_add_gui_rostest name)
    set(result rostest-test_ros_${name}.xml)
    catkin_run_tests_target("rostest" test_ros_${name}.test ${result}
      COMMAND "${PROJECT_SOURCE_DIR}/test/ros/gui_rostest.sh \
${CATKIN_TEST_RESULTS_DIR}/${PROJECT_NAME}/${result} \
${PYTHON_EXECUTABLE} ${KINEMATIC_COVERAGE_ROSTEST} --pkgdir=${PROJECT_SOURCE_DIR} --package=${PROJECT_NAME} \
--results-filename test_ros_${name}.xml --results-base-dir \"${CATKIN_TEST_RESULTS_DIR}\" \
${PROJECT_SOURCE_DIR}/test/ros/${name}.test"
      DEPENDENCIES ${KC_NODE_TARGETS} ${PROJECT_NAME}_rviz_plugins)
    # One GUI test at a time: xdotool drives the display's one pointer and keyboard.
    set_tests_properties(_ctest_${PROJECT_NAME}_rostest_test_ros_${name}.test PROPERTIES
      SKIP_RETURN_CODE 77 RESOURCE_LOCK display)
  endfunction()
  # Set Start, Set Goal and Activate clicked in rviz.
  kc_add_gui_rostest(rviz_tool)
  # The Draw Polygon tool: a hull and a hole drawn by clicks, then planned around the hole.
  kc_add_gui_rostest(polygon_tool)
  # The launch files name only packages and arguments that exist.
  find_package(roslaunch REQUIRED)
  roslaunch_add_file_check(launch)
  # `catkin_make install`: the installed nodes run mission.launch from the install space.
  add_test(NAME install_space
    COMMAND ${PROJECT_SOURCE_DIR}/test/ros/install_space_test.sh ${CMAKE_BINARY_DIR})
  set_tests_properties(install_space PROPERTIES TIMEOUT 180)
endif()
