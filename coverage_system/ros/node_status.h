#pragma once

#include <ros/ros.h>

#include <string>

namespace kinematic_coverage::nodes {

/// A node's `~status` (kinematic_coverage/PlanStatus, latched; docs/REFERENCE.md, Messages):
/// every outcome of a request is published there, and a refused one is also logged as one
/// ROS_ERROR naming the node and the stage, so that a user sees it whether they watch the
/// topic or the log.
class NodeStatus {
 public:
  NodeStatus() = default;

  /// Advertises `~status` on `private_node`; `node_name` and `stage` ("smooth", "replan")
  /// name the outcomes.
  NodeStatus(ros::NodeHandle& private_node, std::string node_name, std::string stage);

  /// Publishes an outcome of the node's stage, or of `stage` when given.
  void publish(bool success, const std::string& message, double duration_s,
               const std::string& frame_id, const std::string& stage = "") const;

  /// A refused request: one ROS_ERROR and a failed status.
  void reject(const std::string& message, double duration_s, const std::string& frame_id) const;

 private:
  ros::Publisher publisher_;
  std::string node_name_;
  std::string stage_;
};

}  // namespace kinematic_coverage::nodes
