#pragma once

#include <geometry_msgs/PointStamped.h>
#include <ros/ros.h>
#include <std_msgs/Empty.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <optional>
#include <string>

#include "coverage_system/mission/mission.h"
#include "coverage_system/ros/node_status.h"
#include "kinematic_coverage/PolygonWithHolesStamped.h"
#include "kinematic_coverage/SaveMission.h"

namespace kinematic_coverage::nodes {

/// The `coverage_planner` node (docs/REFERENCE.md, Nodes and topics): keeps the newest
/// polygon, start and goal, plans with the core's planMission on `activate` or a `~plan` call
/// (or, with `~plan_on_receive`, as soon as all three are known and whenever one changes),
/// and publishes the waypoints on `waypoint_list`, what it computed on `~markers` and the
/// outcome of every request on `~status` (latched, so a late subscriber sees the last one). Start
/// and goal in another frame than the polygon's are transformed with tf2. Bad input gives one
/// ROS_ERROR, a failed status and no output; the node keeps running.
class CoveragePlannerNode {
 public:
  /// Subscribes and advertises in `node`'s namespace (relative names) and under
  /// `private_node` (~markers, ~status, ~plan, ~save_mission); parameters are read from
  /// `private_node` at every request, so `rosparam set` takes effect at the next plan.
  CoveragePlannerNode(const ros::NodeHandle& node, const ros::NodeHandle& private_node);

 private:
  void onPolygon(const kinematic_coverage::PolygonWithHolesStamped::ConstPtr& message);
  void onStart(const geometry_msgs::PointStamped::ConstPtr& message);
  void onGoal(const geometry_msgs::PointStamped::ConstPtr& message);
  void onActivate(const std_msgs::Empty::ConstPtr& message);
  bool onPlanService(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);
  /// `~save_mission`: writes currentMission() as a mission file (MissionFileWriter).
  bool onSaveMissionService(kinematic_coverage::SaveMission::Request& request,
                            kinematic_coverage::SaveMission::Response& response);

  /// The newest polygon, start and goal (in the polygon's frame) with the parameters read
  /// now. Throws core::InvalidInputError when one is missing or a parameter is invalid.
  core::Mission currentMission() const;

  /// Draws the inputs received so far on `~markers` (inputMarkers), as soon as each arrives.
  void publishInputMarkers();

  /// Plans when `plan_on_receive` is set and every input is known; a `plan_on_receive` that
  /// is not true or false is a failed request.
  void planIfReceiving();

  /// Plans with the newest inputs and publishes; returns whether it succeeded, and the
  /// error or a one-line summary in `message`.
  bool plan(std::string& message);

  /// The point in the polygon's frame (tf2 when the frames differ; an empty frame is `map`). Throws
  /// core::InvalidInputError when no transform is available.
  geometry_msgs::PointStamped inPolygonFrame(const geometry_msgs::PointStamped& point,
                                             const std::string& what) const;

  void publishStatus(const std::string& stage, bool success, const std::string& message,
                     double duration_s);

  ros::NodeHandle node_;
  ros::NodeHandle private_node_;
  ros::Subscriber polygon_subscriber_;
  ros::Subscriber start_subscriber_;
  ros::Subscriber goal_subscriber_;
  ros::Subscriber activate_subscriber_;
  ros::Publisher waypoint_publisher_;
  ros::Publisher marker_publisher_;
  NodeStatus status_;
  ros::ServiceServer plan_service_;
  ros::ServiceServer save_mission_service_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  std::optional<kinematic_coverage::PolygonWithHolesStamped> polygon_;
  std::optional<geometry_msgs::PointStamped> start_;
  std::optional<geometry_msgs::PointStamped> goal_;
};

}  // namespace kinematic_coverage::nodes
