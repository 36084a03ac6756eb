#pragma once

#include <geometry_msgs/PointStamped.h>
#include <geometry_msgs/PoseArray.h>
#include <geometry_msgs/PoseStamped.h>
#include <ros/ros.h>

#include <optional>
#include <string>

#include "coverage_system/ros/node_status.h"
#include "kinematic_coverage/PolygonWithHolesStamped.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/replanning/visited_history.h"

namespace kinematic_coverage::nodes {

/// The `replanner` node (docs/REFERENCE.md, Nodes and topics; thesis Sec. 3.4): keeps the visited
/// history in bounded memory (core::VisitedHistory; `visited` replaces it, each `pose` is
/// appended) and the last `goal`; each `updated_polygon` triggers one replan with the core's
/// Replanner, from the last visited pose to the goal over the remaining area
/// (`replanning_method`). Publishes the new `waypoint_list` (the smoother then produces the
/// new trajectory against the same updated polygon), the remaining area on
/// `remaining_polygon` and every outcome on `~status`. `visited` and `pose` must be in the
/// frame of the newest `polygon` or `updated_polygon` (or, before any, of the history) and
/// finite with unit quaternions. Bad input gives one ROS_ERROR, a failed status and no
/// output; the node keeps running.
class ReplannerNode {
 public:
  ReplannerNode(const ros::NodeHandle& node, const ros::NodeHandle& private_node);

 private:
  void onPolygon(const kinematic_coverage::PolygonWithHolesStamped::ConstPtr& message);
  void onUpdatedPolygon(const kinematic_coverage::PolygonWithHolesStamped::ConstPtr& message);
  void onVisited(const geometry_msgs::PoseArray::ConstPtr& message);
  void onPose(const geometry_msgs::PoseStamped::ConstPtr& message);
  void onGoal(const geometry_msgs::PointStamped::ConstPtr& message);

  /// Throws core::InvalidInputError when `frame`, the frame of a `what` message, is not
  /// the polygon's frame (or, before any polygon, the history's).
  void checkHistoryFrame(const std::string& what, const std::string& frame) const;

  /// Whether `message` is the history followed by more poses, as a robot republishing its
  /// growing `visited` sends it: then only the new poses need adding.
  bool extendsHistory(const geometry_msgs::PoseArray& message, const std::string& frame) const;

  ros::NodeHandle node_;
  ros::NodeHandle private_node_;
  ros::Subscriber polygon_subscriber_;
  ros::Subscriber updated_polygon_subscriber_;
  ros::Subscriber visited_subscriber_;
  ros::Subscriber pose_subscriber_;
  ros::Subscriber goal_subscriber_;
  ros::Publisher waypoint_publisher_;
  ros::Publisher remaining_publisher_;
  NodeStatus status_;
  /// Frame of the newest `polygon` or `updated_polygon`.
  std::optional<std::string> polygon_frame_;
  /// The visited poses (with the parameters read when it began), their frame and the
  /// first one.
  std::optional<core::VisitedHistory> history_;
  std::string history_frame_;
  geometry_msgs::Pose first_visited_;
  std::optional<geometry_msgs::PointStamped> goal_;
};

}  // namespace kinematic_coverage::nodes
