# The ROS adapter of smoothing and trajectory generation (catkin builds only). Targets carry
# the package's name; the programs keep the node names.
add_executable(${PROJECT_NAME}_smooth_trajectory_generator
  trajectory_generation_tools/ros/smooth_trajectory_generator_main.cpp
  trajectory_generation_tools/ros/smooth_trajectory_generator_node.cpp)
set_target_properties(${PROJECT_NAME}_smooth_trajectory_generator PROPERTIES
  OUTPUT_NAME smooth_trajectory_generator)
target_link_libraries(${PROJECT_NAME}_smooth_trajectory_generator PRIVATE kc_ros_bridge)
set(KC_NODE_TARGETS ${KC_NODE_TARGETS} ${PROJECT_NAME}_smooth_trajectory_generator)

add_executable(${PROJECT_NAME}_replanner
  trajectory_generation_tools/ros/replanner_main.cpp
  trajectory_generation_tools/ros/replanner_node.cpp)
set_target_properties(${PROJECT_NAME}_replanner PROPERTIES OUTPUT_NAME replanner)
target_link_libraries(${PROJECT_NAME}_replanner PRIVATE kc_ros_bridge)
set(KC_NODE_TARGETS ${KC_NODE_TARGETS} ${PROJECT_NAME}_replanner)

add_executable(${PROJECT_NAME}_auv_simulator
  trajectory_generation_tools/ros/auv_simulator_main.cpp
  trajectory_generation_tools/ros/auv_simulator_node.cpp)
set_target_properties(${PROJECT_NAME}_auv_simulator PROPERTIES OUTPUT_NAME auv_simulator)
target_link_libraries(${PROJECT_NAME}_auv_simulator PRIVATE kc_ros_bridge)
set(KC_NODE_TARGETS ${KC_NODE_TARGETS} ${PROJECT_NAME}_auv_simulator)
