# The ROS adapter of smoothing and trajectory generation (catkin builds only).
add_executable(smooth_trajectory_generator
  trajectory_generation_tools/ros/smooth_trajectory_generator_node.cpp
  trajectory_generation_tools/ros/smooth_trajectory_generator_main.cpp)
target_link_libraries(smooth_trajectory_generator PRIVATE kc_ros_bridge)
set(KC_NODE_TARGETS ${KC_NODE_TARGETS} smooth_trajectory_generator)

add_executable(replanner
  trajectory_generation_tools/ros/replanner_node.cpp
  trajectory_generation_tools/ros/replanner_main.cpp)
target_link_libraries(replanner PRIVATE kc_ros_bridge)
set(KC_NODE_TARGETS ${KC_NODE_TARGETS} replanner)

add_executable(auv_simulator
  trajectory_generation_tools/ros/auv_simulator_node.cpp
  trajectory_generation_tools/ros/auv_simulator_main.cpp)
target_link_libraries(auv_simulator PRIVATE kc_ros_bridge)
set(KC_NODE_TARGETS ${KC_NODE_TARGETS} auv_simulator)
