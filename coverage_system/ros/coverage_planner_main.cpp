// The coverage_planner node (docs/REFERENCE.md, Nodes and topics).

#include <ros/ros.h>

#include "coverage_system/ros/coverage_planner_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "coverage_planner");
  kinematic_coverage::nodes::CoveragePlannerNode node(ros::NodeHandle(), ros::NodeHandle("~"));
  ros::spin();
  return 0;
}
