#include "trajectory_generation_tools/ros/replanner_node.h"

#include <visualization_msgs/MarkerArray.h>

#include <chrono>
#include <sstream>

#include "kinematic_coverage/PlanStatus.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/ros/message_conversion.h"
#include "polygon_coverage_ros_bridge/ros/plan_markers.h"
#include "polygon_coverage_ros_bridge/ros/ros_parameter_reader.h"
#include "trajectory_generation_tools/replanning/replanner.h"

namespace kinematic_coverage::nodes {

ReplannerNode::ReplannerNode(const ros::NodeHandle& node, const ros::NodeHandle& private_node)
    : node_(node), private_node_(private_node) {
  waypoint_publisher_ = node_.advertise<geometry_msgs::PoseArray>("waypoint_list", 1, true);
  remaining_publisher_ =
      node_.advertise<visualization_msgs::MarkerArray>("remaining_polygon", 1, true);
  status_publisher_ = private_node_.advertise<kinematic_coverage::PlanStatus>("status", 10, true);
  updated_polygon_subscriber_ =
      node_.subscribe("updated_polygon", 1, &ReplannerNode::onUpdatedPolygon, this);
  visited_subscriber_ = node_.subscribe("visited", 1, &ReplannerNode::onVisited, this);
  pose_subscriber_ = node_.subscribe("pose", 100, &ReplannerNode::onPose, this);
  goal_subscriber_ = node_.subscribe("goal", 1, &ReplannerNode::onGoal, this);
  ROS_INFO("replanner: waiting for visited poses, a goal and an updated_polygon");
}

void ReplannerNode::onVisited(const geometry_msgs::PoseArray::ConstPtr& message) {
  visited_ = fromPoseArray(*message);
}

void ReplannerNode::onPose(const geometry_msgs::PoseStamped::ConstPtr& message) {
  visited_.push_back(
      {message->pose.position.x, message->pose.position.y, yawOf(message->pose.orientation)});
}

void ReplannerNode::onGoal(const geometry_msgs::PointStamped::ConstPtr& message) {
  goal_ = *message;
}

void ReplannerNode::onUpdatedPolygon(
    const kinematic_coverage::PolygonWithHolesStamped::ConstPtr& message) {
  const auto start = std::chrono::steady_clock::now();
  const std::string frame = message->header.frame_id.empty() ? "map" : message->header.frame_id;
  std::string error;
  try {
    if (!goal_) throw core::InvalidInputError("cannot replan: no goal received");
    if (!goal_->header.frame_id.empty() && goal_->header.frame_id != frame) {
      throw core::InvalidInputError("the goal is in frame '" + goal_->header.frame_id +
                                    "' but the updated polygon in frame '" + frame + "'");
    }
    const core::PlannerParameters parameters = readPlannerParameters(private_node_);
    const core::ReplannedMission replanned =
        core::Replanner(parameters)
            .replan(fromMessage(message->polygon), visited_, fromMessage(goal_->point),
                    [](const core::PlanningStage& stage) {
                      ROS_INFO("replanner: %s: %s (%.3f s)", stage.name.c_str(),
                               stage.summary.c_str(), stage.duration_s);
                    });
    for (const std::string& warning : replanned.warnings) {
      ROS_WARN("replanner: %s", warning.c_str());
    }
    std_msgs::Header header;
    header.frame_id = frame;
    header.stamp = ros::Time::now();
    waypoint_publisher_.publish(toPoseArray(replanned.plan.waypoints, header));
    visualization_msgs::MarkerArray remaining;
    remaining.markers.push_back(deleteAllMarker(header));
    int id = 0;
    for (const core::PolygonWithHoles& part : replanned.remaining.parts) {
      remaining.markers.push_back(
          ringMarker(part.hull, "remaining_polygon", id++, header, 0.9f, 0.2f, 0.2f, 0.08));
      for (const core::Ring& hole : part.holes) {
        remaining.markers.push_back(
            ringMarker(hole, "remaining_polygon", id++, header, 0.9f, 0.5f, 0.5f, 0.05));
      }
    }
    remaining_publisher_.publish(remaining);
    std::ostringstream summary;
    summary.precision(4);
    summary << replanned.remaining.parts.size() << " remaining parts ("
            << replanned.remaining.kept_area_m2 << " m^2), " << replanned.plan.waypoints.size()
            << " waypoints from the last of " << visited_.size() << " visited poses";
    const double duration_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ROS_INFO("replanner: replan: %s (%.3f s)", summary.str().c_str(), duration_s);
    publishStatus(true, summary.str(), duration_s, frame);
    return;
  } catch (const core::InvalidInputError& invalid) {
    error = invalid.what();
  } catch (const std::exception& internal) {
    error = std::string("internal error: ") + internal.what();
  }
  ROS_ERROR("replanner: replan: %s", error.c_str());
  publishStatus(false, error,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                frame);
}

void ReplannerNode::publishStatus(bool success, const std::string& message, double duration_s,
                                  const std::string& frame_id) {
  status_publisher_.publish(statusMessage("replan", success, message, duration_s, frame_id));
}

}  // namespace kinematic_coverage::nodes
