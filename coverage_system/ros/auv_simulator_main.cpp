// The auv_simulator node (docs/REFERENCE.md, Nodes and topics).

#include <ros/ros.h>

#include "coverage_system/ros/auv_simulator_node.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "auv_simulator");
  // The handles outlive the node: the last one's end shuts ROS down, and with it the log
  // that ROS_FATAL writes to.
  ros::NodeHandle node;
  ros::NodeHandle private_node("~");
  try {
    kinematic_coverage::nodes::AuvSimulatorNode simulator(node, private_node);
    ros::spin();
  } catch (const kinematic_coverage::core::InvalidInputError& error) {
    ROS_FATAL("auv_simulator: %s", error.what());
    return 2;
  }
  return 0;
}
