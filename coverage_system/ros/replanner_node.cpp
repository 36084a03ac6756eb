#include "coverage_system/ros/replanner_node.h"

#include <visualization_msgs/MarkerArray.h>

#include <chrono>
#include <sstream>
#include <vector>

#include "coverage_system/parameters/stage_options.h"
#include "coverage_system/planner/replanner.h"
#include "coverage_system/ros/message_conversion.h"
#include "coverage_system/ros/plan_markers.h"
#include "coverage_system/ros/ros_parameter_reader.h"
#include "polygon_coverage_ros_bridge/base/elapsed_seconds.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::nodes {
namespace {

using core::secondsSince;

bool samePose(const geometry_msgs::Pose& a, const geometry_msgs::Pose& b) {
  return a.position.x == b.position.x && a.position.y == b.position.y &&
         a.orientation.x == b.orientation.x && a.orientation.y == b.orientation.y &&
         a.orientation.z == b.orientation.z && a.orientation.w == b.orientation.w;
}

/// The poses [from, end) of a message, each checked as its message's and the history's
/// (named `what` and its index).
std::vector<core::Pose2> checkedVisited(const geometry_msgs::PoseArray& message, std::size_t from,
                                        const std::string& what) {
  std::vector<core::Pose2> poses;
  poses.reserve(message.poses.size() - from);
  for (std::size_t i = from; i < message.poses.size(); ++i) {
    const std::string name = what + " " + std::to_string(i);
    poses.push_back(checkedPose(message.poses[i], name));
    core::VisitedHistory::check(poses.back(), name);
  }
  return poses;
}

}  // namespace

ReplannerNode::ReplannerNode(const ros::NodeHandle& node, const ros::NodeHandle& private_node)
    : node_(node), private_node_(private_node) {
  waypoint_publisher_ = node_.advertise<geometry_msgs::PoseArray>("waypoint_list", 1, true);
  remaining_publisher_ =
      node_.advertise<visualization_msgs::MarkerArray>("remaining_polygon", 1, true);
  status_ = NodeStatus(private_node_, "replanner", "replan");
  polygon_subscriber_ = node_.subscribe("polygon", 1, &ReplannerNode::onPolygon, this);
  updated_polygon_subscriber_ =
      node_.subscribe("updated_polygon", 1, &ReplannerNode::onUpdatedPolygon, this);
  visited_subscriber_ = node_.subscribe("visited", 1, &ReplannerNode::onVisited, this);
  pose_subscriber_ = node_.subscribe("pose", 100, &ReplannerNode::onPose, this);
  goal_subscriber_ = node_.subscribe("goal", 1, &ReplannerNode::onGoal, this);
  ROS_INFO("replanner: waiting for visited poses, a goal and an updated_polygon");
}

void ReplannerNode::onPolygon(
    const kinematic_coverage::PolygonWithHolesStamped::ConstPtr& message) {
  polygon_frame_ = frameOf(message->header);
}

void ReplannerNode::checkHistoryFrame(const std::string& what, const std::string& frame) const {
  if (polygon_frame_) {
    if (frame != *polygon_frame_) {
      throw core::InvalidInputError(what + " is in frame '" + frame +
                                    "' but the polygon is in frame '" + *polygon_frame_ + "'");
    }
  } else if (history_ && frame != history_frame_) {
    throw core::InvalidInputError(what + " is in frame '" + frame +
                                  "' but the visited history is in frame '" + history_frame_ + "'");
  }
}

bool ReplannerNode::extendsHistory(const geometry_msgs::PoseArray& message,
                                   const std::string& frame) const {
  if (!history_ || history_->empty() || frame != history_frame_) return false;
  const std::size_t count = history_->count();
  if (message.poses.size() < count || !samePose(message.poses.front(), first_visited_)) {
    return false;
  }
  const core::Pose2& last = history_->last();
  const geometry_msgs::Pose& candidate = message.poses[count - 1];
  return candidate.position.x == last.x && candidate.position.y == last.y &&
         yawOf(candidate.orientation) == last.yaw;
}

void ReplannerNode::onVisited(const geometry_msgs::PoseArray::ConstPtr& message) {
  const auto start = std::chrono::steady_clock::now();
  const std::string frame = frameOf(message->header);
  try {
    // A `visited` replaces the history, so before any polygon it may change the frame.
    if (polygon_frame_) checkHistoryFrame("visited", frame);
    if (extendsHistory(*message, frame)) {
      for (const core::Pose2& pose : checkedVisited(*message, history_->count(), "visited pose")) {
        history_->add(pose);
      }
      return;
    }
    const std::vector<core::Pose2> poses = checkedVisited(*message, 0, "visited pose");
    core::VisitedHistory history(core::sensorOf(readPlannerParameters(private_node_)));
    for (const core::Pose2& pose : poses) history.add(pose);
    history_ = std::move(history);
    history_frame_ = frame;
    if (!message->poses.empty()) first_visited_ = message->poses.front();
  } catch (const core::InvalidInputError& error) {
    status_.reject(std::string("visited: ") + error.what(), secondsSince(start), frame);
  } catch (const std::exception& error) {
    status_.reject(std::string("internal error: visited: ") + error.what(), secondsSince(start),
                   frame);
  }
}

void ReplannerNode::onPose(const geometry_msgs::PoseStamped::ConstPtr& message) {
  const auto start = std::chrono::steady_clock::now();
  const std::string frame = frameOf(message->header);
  try {
    checkHistoryFrame("pose", frame);
    const core::Pose2 pose = checkedPose(message->pose, "pose");
    core::VisitedHistory::check(pose, "pose");
    if (!history_) {
      history_.emplace(core::sensorOf(readPlannerParameters(private_node_)));
      history_frame_ = frame;
    }
    if (history_->empty()) first_visited_ = message->pose;
    history_->add(pose);
  } catch (const core::InvalidInputError& error) {
    status_.reject(std::string("pose: ") + error.what(), secondsSince(start), frame);
  } catch (const std::exception& error) {
    status_.reject(std::string("internal error: pose: ") + error.what(), secondsSince(start),
                   frame);
  }
}

void ReplannerNode::onGoal(const geometry_msgs::PointStamped::ConstPtr& message) {
  goal_ = *message;
}

void ReplannerNode::onUpdatedPolygon(
    const kinematic_coverage::PolygonWithHolesStamped::ConstPtr& message) {
  const auto start = std::chrono::steady_clock::now();
  const std::string frame = frameOf(message->header);
  polygon_frame_ = frame;
  std::string error;
  try {
    if (!goal_) throw core::InvalidInputError("cannot replan: no goal received");
    if (frameOf(goal_->header) != frame) {
      throw core::InvalidInputError("the goal is in frame '" + frameOf(goal_->header) +
                                    "' but the updated polygon in frame '" + frame + "'");
    }
    if (!history_ || history_->empty()) {
      throw core::InvalidInputError(
          "no visited poses: replanning starts from the last visited pose");
    }
    if (history_frame_ != frame) {
      throw core::InvalidInputError("the visited poses are in frame '" + history_frame_ +
                                    "' but the updated polygon in frame '" + frame + "'");
    }
    const core::PlannerParameters parameters = readPlannerParameters(private_node_);
    const core::ReplannedMission replanned =
        core::Replanner(parameters)
            .replan(fromMessage(message->polygon), *history_, fromMessage(goal_->point),
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
            << " waypoints from the last of " << history_->count() << " visited poses";
    const double duration_s = secondsSince(start);
    ROS_INFO("replanner: replan: %s (%.3f s)", summary.str().c_str(), duration_s);
    status_.publish(true, summary.str(), duration_s, frame);
    return;
  } catch (const core::InvalidInputError& invalid) {
    error = invalid.what();
  } catch (const std::exception& internal) {
    error = std::string("internal error: ") + internal.what();
  }
  status_.reject(error, secondsSince(start), frame);
}

}  // namespace kinematic_coverage::nodes
