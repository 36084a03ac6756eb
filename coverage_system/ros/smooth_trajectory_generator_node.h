#pragma once

#include <geometry_msgs/PoseArray.h>
#include <ros/ros.h>

#include <optional>
#include <string>
#include <vector>

#include "coverage_system/ros/node_status.h"
#include "kinematic_coverage/PolygonWithHolesStamped.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::nodes {

/// The `smooth_trajectory_generator` node (docs/REFERENCE.md, Nodes and topics): smooths every
/// `waypoint_list` it receives against the newest of `polygon` and `updated_polygon`
/// (Algorithm 1 with the raw hull and holes), samples and times it with the core's
/// TrajectoryGenerator, and publishes `trajectory`, `trajectory_path` (stamped with the
/// time of planning plus each pose's time offset), `~markers` (the smoothed path by
/// variant), `~coverage_heatmap` (an OccupancyGrid, heatmapGrid) and `~status`. A polygon is
/// validated and cleaned when it arrives; a waypoint list is checked when it arrives (at least one
/// pose, finite positions, unit quaternions, the polygon's frame) and one that arrives before any
/// valid polygon waits for one. Bad input (an invalid polygon, a bad waypoint list, parameters)
/// gives one ROS_ERROR, a failed status and no output; the node keeps running.
class SmoothTrajectoryGeneratorNode {
 public:
  /// Topics are relative to `node`; ~markers and ~status and the parameters (read at every
  /// request) are under `private_node`.
  SmoothTrajectoryGeneratorNode(const ros::NodeHandle& node, const ros::NodeHandle& private_node);

 private:
  void onPolygon(const kinematic_coverage::PolygonWithHolesStamped::ConstPtr& message);
  void onWaypoints(const geometry_msgs::PoseArray::ConstPtr& message);

  /// Smooths the pending waypoint list against the newest polygon and publishes.
  void generate();

  ros::NodeHandle node_;
  ros::NodeHandle private_node_;
  ros::Subscriber polygon_subscriber_;
  ros::Subscriber updated_polygon_subscriber_;
  ros::Subscriber waypoint_subscriber_;
  ros::Publisher trajectory_publisher_;
  ros::Publisher path_publisher_;
  ros::Publisher marker_publisher_;
  ros::Publisher heatmap_publisher_;
  NodeStatus status_;
  /// The newest valid polygon, cleaned, and its frame (docs/REFERENCE.md, Messages).
  std::optional<core::PolygonWithHoles> free_area_;
  std::string polygon_frame_;
  /// The waypoint list waiting for a polygon or being smoothed, checked, and its frame.
  std::optional<std::vector<core::Pose2>> waypoints_;
  std::string waypoint_frame_;
};

}  // namespace kinematic_coverage::nodes
