# The one ROS adapter layer of every node (catkin builds only), as grid_map_ros converts
# for grid_map_core: message conversion and status, parameter reading, the markers of
# plans, trajectories and coverage; and the nodes coverage_planner and mission_publisher.
add_library(kc_ros_bridge STATIC
  polygon_coverage_ros_bridge/ros/message_conversion.cpp
  polygon_coverage_ros_bridge/ros/ros_parameter_reader.cpp
  polygon_coverage_ros_bridge/ros/plan_markers.cpp
  polygon_coverage_ros_bridge/ros/trajectory_markers.cpp
  polygon_coverage_ros_bridge/ros/heatmap_grid.cpp
  polygon_coverage_ros_bridge/ros/coverage_planner_node.cpp)
target_include_directories(kc_ros_bridge PUBLIC ${PROJECT_SOURCE_DIR} ${catkin_INCLUDE_DIRS}
  ${CATKIN_DEVEL_PREFIX}/${CATKIN_GLOBAL_INCLUDE_DESTINATION})
target_link_libraries(kc_ros_bridge PUBLIC kinematic_coverage_core ${catkin_LIBRARIES})
target_compile_options(kc_ros_bridge PRIVATE -Wall -Wextra)
add_dependencies(kc_ros_bridge ${PROJECT_NAME}_generate_messages_cpp ${catkin_EXPORTED_TARGETS})

add_executable(coverage_planner polygon_coverage_ros_bridge/ros/coverage_planner_main.cpp)
target_link_libraries(coverage_planner PRIVATE kc_ros_bridge)
set(KC_NODE_TARGETS ${KC_NODE_TARGETS} coverage_planner)

add_executable(mission_publisher polygon_coverage_ros_bridge/ros/mission_publisher_main.cpp)
target_link_libraries(mission_publisher PRIVATE kc_ros_bridge)
set(KC_NODE_TARGETS ${KC_NODE_TARGETS} mission_publisher)
