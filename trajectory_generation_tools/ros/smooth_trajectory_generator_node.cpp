#include "trajectory_generation_tools/ros/smooth_trajectory_generator_node.h"

#include <nav_msgs/Path.h>
#include <visualization_msgs/MarkerArray.h>

#include <chrono>
#include <sstream>
#include <vector>

#include "kinematic_coverage/PlanStatus.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/ros/message_conversion.h"
#include "polygon_coverage_ros_bridge/ros/ros_parameter_reader.h"
#include "polygon_coverage_ros_bridge/validation/polygon_cleaner.h"
#include "polygon_coverage_ros_bridge/validation/polygon_validator.h"
#include "trajectory_generation_tools/ros/heatmap_markers.h"
#include "trajectory_generation_tools/ros/trajectory_markers.h"
#include "trajectory_generation_tools/trajectory/trajectory_generator.h"

namespace kinematic_coverage::nodes {

SmoothTrajectoryGeneratorNode::SmoothTrajectoryGeneratorNode(const ros::NodeHandle& node,
                                                             const ros::NodeHandle& private_node)
    : node_(node), private_node_(private_node) {
  trajectory_publisher_ = node_.advertise<geometry_msgs::PoseArray>("trajectory", 1, true);
  path_publisher_ = node_.advertise<nav_msgs::Path>("trajectory_path", 1, true);
  marker_publisher_ = private_node_.advertise<visualization_msgs::MarkerArray>("markers", 1, true);
  status_publisher_ = private_node_.advertise<kinematic_coverage::PlanStatus>("status", 10, true);
  polygon_subscriber_ =
      node_.subscribe("polygon", 1, &SmoothTrajectoryGeneratorNode::onPolygon, this);
  updated_polygon_subscriber_ =
      node_.subscribe("updated_polygon", 1, &SmoothTrajectoryGeneratorNode::onPolygon, this);
  waypoint_subscriber_ =
      node_.subscribe("waypoint_list", 1, &SmoothTrajectoryGeneratorNode::onWaypoints, this);
  ROS_INFO("smooth_trajectory_generator: waiting for a polygon and a waypoint_list");
}

void SmoothTrajectoryGeneratorNode::onPolygon(
    const kinematic_coverage::PolygonWithHolesStamped::ConstPtr& message) {
  const bool waiting = waypoints_.has_value() && !polygon_.has_value();
  polygon_ = *message;
  ROS_INFO("smooth_trajectory_generator: polygon received (%zu holes, frame %s)",
           message->polygon.holes.size(), message->header.frame_id.c_str());
  if (waiting) generate();
}

void SmoothTrajectoryGeneratorNode::onWaypoints(const geometry_msgs::PoseArray::ConstPtr& message) {
  waypoints_ = *message;
  ROS_INFO("smooth_trajectory_generator: waypoint_list of %zu waypoints received",
           message->poses.size());
  if (!polygon_) {
    ROS_INFO("smooth_trajectory_generator: waiting for a polygon to smooth against");
    return;
  }
  generate();
}

void SmoothTrajectoryGeneratorNode::generate() {
  const auto start = std::chrono::steady_clock::now();
  const std::string frame = waypoints_->header.frame_id;
  std::string message;
  try {
    if (!polygon_->header.frame_id.empty() && !frame.empty() &&
        polygon_->header.frame_id != frame) {
      throw core::InvalidInputError("waypoint_list is in frame '" + frame +
                                    "' but the polygon is in frame '" + polygon_->header.frame_id +
                                    "'");
    }
    const core::PlannerParameters parameters = readPlannerParameters(private_node_);
    const core::PolygonWithHoles raw = fromMessage(polygon_->polygon);
    core::PolygonValidator().validate(raw);
    const core::CleanedPolygon cleaned = core::PolygonCleaner().clean(raw);
    const core::GeneratedTrajectory trajectory =
        core::TrajectoryGenerator(parameters)
            .generate(fromPoseArray(*waypoints_), cleaned.free_area);
    std_msgs::Header header;
    header.frame_id = frame.empty() ? polygon_->header.frame_id : frame;
    header.stamp = ros::Time::now();
    trajectory_publisher_.publish(toPoseArray(trajectory.poses, header));
    path_publisher_.publish(toPath(trajectory.poses, header));
    visualization_msgs::MarkerArray markers = trajectoryMarkers(trajectory.path, header);
    std::vector<core::Pose2> poses;
    poses.reserve(trajectory.poses.size());
    for (const core::TrajectoryPose& pose : trajectory.poses) {
      poses.push_back({pose.x, pose.y, pose.yaw});
    }
    markers.markers.push_back(heatmapMarker(cleaned.free_area, poses, parameters, header));
    marker_publisher_.publish(markers);
    const core::SmoothingStatistics& turns = trajectory.statistics;
    std::ostringstream summary;
    summary << turns.turns_smoothed << " of " << turns.turns_total << " turns smoothed (inner "
            << turns.inner << ", outer bisector " << turns.outer_bisector << ", outer tangent "
            << turns.outer_tangent << ", reverse curve " << turns.reverse_curve
            << "; kept sharp for coverage " << turns.kept_for_coverage << "), "
            << trajectory.poses.size() << " poses, " << trajectory.trajectory_length_m << " m, "
            << trajectory.traversal_time_s << " s";
    const double duration_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ROS_INFO("smooth_trajectory_generator: smooth: %s (%.3f s)", summary.str().c_str(), duration_s);
    publishStatus(true, summary.str(), duration_s, header.frame_id);
    return;
  } catch (const core::InvalidInputError& error) {
    message = error.what();
  } catch (const std::exception& error) {
    message = std::string("internal error: ") + error.what();
  }
  ROS_ERROR("smooth_trajectory_generator: smooth: %s", message.c_str());
  publishStatus(false, message,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                frame);
}

void SmoothTrajectoryGeneratorNode::publishStatus(bool success, const std::string& message,
                                                  double duration_s, const std::string& frame_id) {
  status_publisher_.publish(statusMessage("smooth", success, message, duration_s, frame_id));
}

}  // namespace kinematic_coverage::nodes
