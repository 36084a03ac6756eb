# rostests of the nodes (catkin builds only): whole flows against running nodes.
if(catkin_FOUND)
  find_package(rostest REQUIRED)
  add_rostest(test/ros/pipeline_lake.test DEPENDENCIES ${KC_NODE_TARGETS})
  add_rostest(test/ros/planner_requests.test DEPENDENCIES ${KC_NODE_TARGETS})
endif()
