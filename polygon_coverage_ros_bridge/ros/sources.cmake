# The one ROS adapter layer of every node (catkin builds only), as grid_map_ros converts
# for grid_map_core: message conversion and status, parameter reading, the markers of
# plans, trajectories and coverage; and the nodes coverage_planner and mission_publisher.
add_library(kc_ros_bridge STATIC
  polygon_coverage_ros_bridge/ros/coverage_planner_node.cpp
  polygon_coverage_ros_bridge/ros/heatmap_grid.cpp
  polygon_coverage_ros_bridge/ros/message_conversion.cpp
  polygon_coverage_ros_bridge/ros/node_status.cpp
  polygon_coverage_ros_bridge/ros/plan_markers.cpp
  polygon_coverage_ros_bridge/ros/ros_parameter_reader.cpp
  polygon_coverage_ros_bridge/ros/trajectory_markers.cpp)
target_include_directories(kc_ros_bridge PUBLIC ${PROJECT_SOURCE_DIR})
target_link_libraries(kc_ros_bridge PUBLIC ${PROJECT_NAME}_core ${catkin_LIBRARIES})
target_compile_options(kc_ros_bridge PRIVATE -Wall -Wextra)
add_dependencies(kc_ros_bridge ${PROJECT_NAME}_generate_messages_cpp ${catkin_EXPORTED_TARGETS})

add_executable(${PROJECT_NAME}_coverage_planner
  polygon_coverage_ros_bridge/ros/coverage_planner_main.cpp)
set_target_properties(${PROJECT_NAME}_coverage_planner PROPERTIES OUTPUT_NAME coverage_planner)
target_link_libraries(${PROJECT_NAME}_coverage_planner PRIVATE kc_ros_bridge)
set(KC_NODE_TARGETS ${KC_NODE_TARGETS} ${PROJECT_NAME}_coverage_planner)

add_executable(${PROJECT_NAME}_mission_publisher
  polygon_coverage_ros_bridge/ros/mission_publisher_main.cpp)
set_target_properties(${PROJECT_NAME}_mission_publisher PROPERTIES OUTPUT_NAME mission_publisher)
target_link_libraries(${PROJECT_NAME}_mission_publisher PRIVATE kc_ros_bridge)
set(KC_NODE_TARGETS ${KC_NODE_TARGETS} ${PROJECT_NAME}_mission_publisher)
