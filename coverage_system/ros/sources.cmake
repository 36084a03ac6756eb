# The one ROS adapter layer of every node (catkin builds only), as grid_map_ros converts
# for grid_map_core: message conversion and status, parameter reading, the markers of
# plans, trajectories and coverage; and the nodes. Targets carry the package's name; the
# programs keep the node names.
add_library(kc_ros_bridge STATIC
  coverage_system/ros/coverage_planner_node.cpp
  coverage_system/ros/heatmap_grid.cpp
  coverage_system/ros/marker_scale.cpp
  coverage_system/ros/message_conversion.cpp
  coverage_system/ros/node_status.cpp
  coverage_system/ros/plan_markers.cpp
  coverage_system/ros/ros_parameter_reader.cpp
  coverage_system/ros/trajectory_markers.cpp)
target_include_directories(kc_ros_bridge PUBLIC ${PROJECT_SOURCE_DIR})
target_link_libraries(kc_ros_bridge PUBLIC ${PROJECT_NAME}_core ${catkin_LIBRARIES})
target_compile_options(kc_ros_bridge PRIVATE -Wall -Wextra)
add_dependencies(kc_ros_bridge ${PROJECT_NAME}_generate_messages_cpp ${catkin_EXPORTED_TARGETS})

add_executable(${PROJECT_NAME}_coverage_planner
  coverage_system/ros/coverage_planner_main.cpp)
set_target_properties(${PROJECT_NAME}_coverage_planner PROPERTIES OUTPUT_NAME coverage_planner)
target_link_libraries(${PROJECT_NAME}_coverage_planner PRIVATE kc_ros_bridge)
set(KC_NODE_TARGETS ${KC_NODE_TARGETS} ${PROJECT_NAME}_coverage_planner)

add_executable(${PROJECT_NAME}_mission_publisher
  coverage_system/ros/mission_publisher_main.cpp)
set_target_properties(${PROJECT_NAME}_mission_publisher PROPERTIES OUTPUT_NAME mission_publisher)
target_link_libraries(${PROJECT_NAME}_mission_publisher PRIVATE kc_ros_bridge)
set(KC_NODE_TARGETS ${KC_NODE_TARGETS} ${PROJECT_NAME}_mission_publisher)

add_executable(${PROJECT_NAME}_smooth_trajectory_generator
  coverage_system/ros/smooth_trajectory_generator_main.cpp
  coverage_system/ros/smooth_trajectory_generator_node.cpp)
set_target_properties(${PROJECT_NAME}_smooth_trajectory_generator PROPERTIES
  OUTPUT_NAME smooth_trajectory_generator)
target_link_libraries(${PROJECT_NAME}_smooth_trajectory_generator PRIVATE kc_ros_bridge)
set(KC_NODE_TARGETS ${KC_NODE_TARGETS} ${PROJECT_NAME}_smooth_trajectory_generator)

add_executable(${PROJECT_NAME}_replanner
  coverage_system/ros/replanner_main.cpp
  coverage_system/ros/replanner_node.cpp)
set_target_properties(${PROJECT_NAME}_replanner PROPERTIES OUTPUT_NAME replanner)
target_link_libraries(${PROJECT_NAME}_replanner PRIVATE kc_ros_bridge)
set(KC_NODE_TARGETS ${KC_NODE_TARGETS} ${PROJECT_NAME}_replanner)

add_executable(${PROJECT_NAME}_auv_simulator
  coverage_system/ros/auv_simulator_main.cpp
  coverage_system/ros/auv_simulator_node.cpp)
set_target_properties(${PROJECT_NAME}_auv_simulator PROPERTIES OUTPUT_NAME auv_simulator)
target_link_libraries(${PROJECT_NAME}_auv_simulator PRIVATE kc_ros_bridge)
set(KC_NODE_TARGETS ${KC_NODE_TARGETS} ${PROJECT_NAME}_auv_simulator)
