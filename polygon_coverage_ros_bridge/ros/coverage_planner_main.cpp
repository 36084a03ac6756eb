// The coverage_planner node (docs/REFERENCE.md, Nodes and topics).

#include <ros/ros.h>

#include "polygon_coverage_ros_bridge/ros/coverage_planner_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "coverage_planner");
  kinematic_coverage::nodes::CoveragePlannerNode node(ros::NodeHandle(), ros::NodeHandle("~"));
  ros::spin();
  return 0;
}
