#pragma once

#include <geometry_msgs/PoseArray.h>
#include <ros/ros.h>

#include <optional>
#include <string>

#include "coverage_system/ros/node_status.h"
#include "trajectory_generation_tools/simulation/trajectory_follower.h"

namespace kinematic_coverage::nodes {

/// The `auv_simulator` node (docs/REFERENCE.md, Nodes and topics): a simulated robot for
/// the whole loop (plan, follow, drift, replan) without a vehicle. It follows each `trajectory` it
/// receives with the core's robot model (TrajectoryFollower, parameters from the private
/// namespace as in config/default.yaml, read at every trajectory), in simulated time that
/// runs `~real_time_factor` times faster than ROS time, and publishes at `~publish_rate`
/// (Hz of ROS time) its `pose` (geometry_msgs/PoseStamped) and `visited`
/// (geometry_msgs/PoseArray, latched: its start and its pose at every tick it moved,
/// oldest first), and `estimated_pose` (PoseStamped: what its navigation believes, the
/// true pose plus the navigation error of navigation_sigma). The first trajectory starts
/// the robot at rest at its first pose and fixes the frame; a newer one restarts the model
/// from the robot's current pose and velocities in the same lake (its current's fluctuation
/// and navigation error run on, unless their parameters changed), keeping the visited
/// history; one with an older header stamp is ignored. `~status`
/// (PlanStatus, stage "simulate") reports each start, the arrival at the last pose and every
/// failure. Bad input (no poses, a non-finite pose or orientation, another frame, a parameter out
/// of range, the last pose not reached within sim_time_limit) gives one ROS_ERROR and a failed
/// status; the node keeps running.
class AuvSimulatorNode {
 public:
  /// Topics are relative to `node`; ~status and the parameters are under `private_node`.
  /// Throws core::InvalidInputError for ~real_time_factor or ~publish_rate not a number
  /// (an integer or a double) or not > 0.
  AuvSimulatorNode(const ros::NodeHandle& node, const ros::NodeHandle& private_node);

 private:
  void onTrajectory(const geometry_msgs::PoseArray::ConstPtr& message);
  /// Advances the model by the simulated time owed since the last tick and publishes.
  void onTick(const ros::TimerEvent& event);
  /// Publishes the robot's true and estimated poses and, if `moved`, appends the true one to
  /// `visited` and publishes that.
  void publishPose(bool moved);
  void publishStatus(bool success, const std::string& message);

  ros::NodeHandle node_;
  ros::NodeHandle private_node_;
  ros::Subscriber trajectory_subscriber_;
  ros::Publisher pose_publisher_;
  ros::Publisher estimated_pose_publisher_;
  ros::Publisher visited_publisher_;
  NodeStatus status_;
  ros::Timer timer_;
  double real_time_factor_ = 10.0;
  std::optional<core::TrajectoryFollower> follower_;
  /// Simulated seconds owed to the model: real time elapsed times the factor, less the
  /// steps taken.
  double owed_time_s_ = 0.0;
  ros::Time last_tick_;
  /// Header stamp of the trajectory being followed.
  ros::Time trajectory_stamp_;
  /// Simulated time at which it began, and sim_time_limit then.
  double trajectory_start_s_ = 0.0;
  double time_limit_s_ = 0.0;
  /// sim_dt of the trajectory being followed.
  double sim_dt_ = 0.1;
  /// Whether the arrival or the time-out of the current trajectory has been reported.
  bool outcome_reported_ = false;
  /// True once this trajectory's reference was reported to ask more than the vehicle can do.
  bool excess_reported_ = false;
  geometry_msgs::PoseArray visited_;
};

}  // namespace kinematic_coverage::nodes
