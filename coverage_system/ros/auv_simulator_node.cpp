#include "coverage_system/ros/auv_simulator_node.h"

#include <geometry_msgs/PoseStamped.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "coverage_system/parameters/stage_options.h"
#include "coverage_system/ros/message_conversion.h"
#include "coverage_system/ros/ros_parameter_reader.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "trajectory_generation_tools/simulation/pose_sequence_timing.h"
#include "trajectory_generation_tools/simulation/robot_model_warnings.h"

namespace kinematic_coverage::nodes {
namespace {

/// Most model steps in one tick, so that a stalled timer does not freeze the node while
/// it catches up; the rest of the owed time is dropped.
constexpr double kMaxStepsPerTick = 100000.0;

double positiveParameter(const ros::NodeHandle& private_node, const std::string& name,
                         double default_value) {
  const double value = readNumberParameter(private_node, name, default_value);
  if (!(std::isfinite(value) && value > 0.0)) {
    throw core::InvalidInputError("~" + name + " = " + std::to_string(value) +
                                  " is out of range: it must be a finite number > 0");
  }
  return value;
}

}  // namespace

AuvSimulatorNode::AuvSimulatorNode(const ros::NodeHandle& node, const ros::NodeHandle& private_node)
    : node_(node), private_node_(private_node) {
  real_time_factor_ = positiveParameter(private_node_, "real_time_factor", 10.0);
  const double publish_rate = positiveParameter(private_node_, "publish_rate", 10.0);
  pose_publisher_ = node_.advertise<geometry_msgs::PoseStamped>("pose", 10);
  estimated_pose_publisher_ = node_.advertise<geometry_msgs::PoseStamped>("estimated_pose", 10);
  visited_publisher_ = node_.advertise<geometry_msgs::PoseArray>("visited", 1, true);
  status_ = NodeStatus(private_node_, "auv_simulator", "simulate");
  trajectory_subscriber_ = node_.subscribe("trajectory", 1, &AuvSimulatorNode::onTrajectory, this);
  timer_ = node_.createTimer(ros::Duration(1.0 / publish_rate), &AuvSimulatorNode::onTick, this);
  ROS_INFO("auv_simulator: waiting for a trajectory (real time factor %g, %g Hz)",
           real_time_factor_, publish_rate);
}

void AuvSimulatorNode::onTrajectory(const geometry_msgs::PoseArray::ConstPtr& message) {
  if (follower_ && message->header.stamp < trajectory_stamp_) {
    ROS_INFO("auv_simulator: ignoring a trajectory older than the one followed");
    return;
  }
  try {
    const core::PlannerParameters parameters = readPlannerParameters(private_node_);
    if (message->poses.empty()) throw core::InvalidInputError("the trajectory has no poses");
    const std::vector<core::Pose2> poses = checkedPoses(*message, "trajectory pose");
    const std::string frame = frameOf(message->header);
    if (follower_ && frame != visited_.header.frame_id) {
      throw core::InvalidInputError("the trajectory is in frame '" + frame +
                                    "' but the robot is in frame '" + visited_.header.frame_id +
                                    "'");
    }
    core::RobotState start;
    if (follower_) {
      start = follower_->state();
      // A robot that arrived holds station at its last pose.
      if (follower_->finished()) {
        start.speed = 0.0;
        start.sway = 0.0;
        start.yaw_rate = 0.0;
      }
    } else {
      start.pose = poses.front();
    }
    const core::RobotModel robot = core::robotModelOf(parameters);
    // The topic's poses carry no times: for the controllers that follow times (timed, los),
    // the planner's velocity model times them.
    const std::vector<double> times = core::usesTrajectoryTimes(robot.controller)
                                          ? core::PoseSequenceTiming(robot.vehicle).times(poses)
                                          : std::vector<double>{};
    for (const std::string& warning : core::robotModelWarnings(robot)) {
      ROS_WARN("auv_simulator: %s", warning.c_str());
    }
    if (follower_ &&
        follower_->disturbance().isLakeOf(robot.disturbance, robot.current_x, robot.current_y)) {
      follower_.emplace(robot, poses, start, core::EnvironmentDisturbance(follower_->disturbance()),
                        times);
    } else {
      if (follower_) {
        ROS_INFO(
            "auv_simulator: the current or disturbance parameters changed: the lake's "
            "disturbances start again from disturbance_seed");
      }
      follower_.emplace(robot, poses, start, times);
    }
    trajectory_stamp_ = message->header.stamp;
    trajectory_start_s_ = start.t;
    time_limit_s_ = parameters.sim_time_limit;
    sim_dt_ = parameters.sim_dt;
    outcome_reported_ = false;
    excess_reported_ = false;
    visited_.header.frame_id = frame;
    if (last_tick_.isZero()) last_tick_ = ros::Time::now();
    std::ostringstream summary;
    summary << "following " << poses.size() << " poses from (" << start.pose.x << ", "
            << start.pose.y << ")";
    ROS_INFO("auv_simulator: %s", summary.str().c_str());
    publishStatus(true, summary.str());
    if (visited_.poses.empty()) publishPose(true);
  } catch (const core::InvalidInputError& error) {
    ROS_ERROR("auv_simulator: simulate: %s", error.what());
    publishStatus(false, error.what());
  } catch (const std::exception& error) {
    ROS_ERROR("auv_simulator: simulate: internal error: %s", error.what());
    publishStatus(false, std::string("internal error: ") + error.what());
  }
}

void AuvSimulatorNode::onTick(const ros::TimerEvent&) {
  if (!follower_) return;
  const ros::Time now = ros::Time::now();
  owed_time_s_ += std::max(0.0, (now - last_tick_).toSec()) * real_time_factor_;
  last_tick_ = now;
  const double steps = std::min(std::floor(owed_time_s_ / sim_dt_), kMaxStepsPerTick);
  owed_time_s_ = std::max(0.0, owed_time_s_ - steps * sim_dt_);
  const double time_before_s = follower_->state().t;
  for (double step = 0.0; step < steps && !follower_->finished(); step += 1.0) {
    if (follower_->state().t - trajectory_start_s_ >= time_limit_s_) break;
    follower_->step();
  }
  const core::ReferenceExcess& excess = follower_->referenceExcess();
  if (excess.duration_s > 0.0 && !excess_reported_) {
    ROS_WARN(
        "auv_simulator: the trajectory asks for more than the vehicle can do at t = %.1f s "
        "near (%.2f, %.2f), on the way to pose %zu of %zu: %s; the robot lags its reference",
        excess.first_t - trajectory_start_s_, excess.first_position.x(), excess.first_position.y(),
        excess.first_pose + 1, follower_->targets().size(), excess.first_demand.c_str());
    excess_reported_ = true;
  }
  if (!follower_->finished() && follower_->state().t - trajectory_start_s_ >= time_limit_s_ &&
      !outcome_reported_) {
    std::ostringstream problem;
    problem << "the robot did not reach the last pose within sim_time_limit = " << time_limit_s_
            << " s (it was driving to pose " << follower_->nextTarget() + 1 << " of "
            << follower_->targets().size() << ")";
    ROS_ERROR("auv_simulator: simulate: %s", problem.str().c_str());
    publishStatus(false, problem.str());
    outcome_reported_ = true;
  }
  if (follower_->finished() && !outcome_reported_) {
    std::ostringstream summary;
    summary << "reached the last pose after " << follower_->state().t - trajectory_start_s_
            << " s of simulated time";
    ROS_INFO("auv_simulator: %s", summary.str().c_str());
    publishStatus(true, summary.str());
    outcome_reported_ = true;
  }

  publishPose(visited_.poses.empty() || follower_->state().t != time_before_s);
}

void AuvSimulatorNode::publishPose(bool moved) {
  std_msgs::Header header;
  header.frame_id = visited_.header.frame_id;
  header.stamp = ros::Time::now();
  const geometry_msgs::PoseArray current =
      toPoseArray({follower_->state().pose, follower_->estimatedPose()}, header);
  geometry_msgs::PoseStamped pose;
  pose.header = header;
  pose.pose = current.poses.front();
  pose_publisher_.publish(pose);
  geometry_msgs::PoseStamped estimated;
  estimated.header = header;
  estimated.pose = current.poses.back();
  estimated_pose_publisher_.publish(estimated);
  if (moved) {
    visited_.header.stamp = header.stamp;
    visited_.poses.push_back(pose.pose);
    visited_publisher_.publish(visited_);
  }
}

void AuvSimulatorNode::publishStatus(bool success, const std::string& message) {
  status_.publish(success, message, 0.0, visited_.header.frame_id);
}

}  // namespace kinematic_coverage::nodes
