// The replanner node (docs/REFERENCE.md, Nodes and topics).

#include <ros/ros.h>

#include "coverage_system/ros/replanner_node.h"
#include "polygon_coverage_ros_bridge/base/huge_page_heap.h"

int main(int argc, char** argv) {
  kinematic_coverage::core::restartWithHugePageHeap(argv);
  ros::init(argc, argv, "replanner");
  kinematic_coverage::nodes::ReplannerNode node(ros::NodeHandle(), ros::NodeHandle("~"));
  ros::spin();
  return 0;
}
