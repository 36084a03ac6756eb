// The smooth_trajectory_generator node (docs/REFERENCE.md, Nodes and topics).

#include <ros/ros.h>

#include "coverage_system/ros/smooth_trajectory_generator_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "smooth_trajectory_generator");
  kinematic_coverage::nodes::SmoothTrajectoryGeneratorNode node(ros::NodeHandle(),
                                                                ros::NodeHandle("~"));
  ros::spin();
  return 0;
}
