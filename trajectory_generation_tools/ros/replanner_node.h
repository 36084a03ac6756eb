#pragma once

#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/PoseStamped.h>
#include <ros/ros.h>

#include <optional>
#include <string>
#include <vector>

#include "kinematic_coverage/PolygonWithHolesStamped.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::nodes {

/// The `replanner` node (docs/REFERENCE.md, Nodes and topics; thesis Sec. 3.4): keeps the visited
/// history (`visited` replaces it, each `pose` is appended) and the last `goal`; each
/// `updated_polygon` triggers one replan with the core's Replanner, from the last visited
/// pose to the goal over the remaining area (`replanning_method`). Publishes the new
/// `waypoint_list` (the smoother then produces the new trajectory against the same
/// updated polygon), the remaining area on `remaining_polygon` and every outcome on
/// `~status`. Bad input gives one ROS_ERROR, a failed status and no output.
class ReplannerNode {
 public:
  ReplannerNode(const ros::NodeHandle& node, const ros::NodeHandle& private_node);

 private:
  void onUpdatedPolygon(const kinematic_coverage::PolygonWithHolesStamped::ConstPtr& message);
  void onVisited(const geometry_msgs::PoseArray::ConstPtr& message);
  void onPose(const geometry_msgs::PoseStamped::ConstPtr& message);
  void onGoal(const geometry_msgs::PointStamped::ConstPtr& message);

  void publishStatus(bool success, const std::string& message, double duration_s,
                     const std::string& frame_id);

  ros::NodeHandle node_;
  ros::NodeHandle private_node_;
  ros::Subscriber updated_polygon_subscriber_;
  ros::Subscriber visited_subscriber_;
  ros::Subscriber pose_subscriber_;
  ros::Subscriber goal_subscriber_;
  ros::Publisher waypoint_publisher_;
  ros::Publisher remaining_publisher_;
  ros::Publisher status_publisher_;
  std::vector<core::Pose2> visited_;
  std::optional<geometry_msgs::PointStamped> goal_;
};

}  // namespace kinematic_coverage::nodes
