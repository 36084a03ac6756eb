// The coverage_planner node (docs/REFERENCE.md, Nodes and topics).

#include <ros/ros.h>

#include "coverage_system/ros/coverage_planner_node.h"
#include "polygon_coverage_ros_bridge/base/huge_page_heap.h"

int main(int argc, char** argv) {
  kinematic_coverage::core::restartWithHugePageHeap(argv);
  ros::init(argc, argv, "coverage_planner");
  kinematic_coverage::nodes::CoveragePlannerNode node(ros::NodeHandle(), ros::NodeHandle("~"));
  ros::spin();
  return 0;
}
