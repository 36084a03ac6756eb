#include "coverage_system/ros/node_status.h"

#include <utility>

#include "coverage_system/ros/message_conversion.h"
#include "kinematic_coverage/PlanStatus.h"

namespace kinematic_coverage::nodes {

NodeStatus::NodeStatus(ros::NodeHandle& private_node, std::string node_name, std::string stage)
    : publisher_(private_node.advertise<kinematic_coverage::PlanStatus>("status", 10, true)),
      node_name_(std::move(node_name)),
      stage_(std::move(stage)) {}

void NodeStatus::publish(bool success, const std::string& message, double duration_s,
                         const std::string& frame_id, const std::string& stage) const {
  publisher_.publish(
      statusMessage(stage.empty() ? stage_ : stage, success, message, duration_s, frame_id));
}

void NodeStatus::reject(const std::string& message, double duration_s,
                        const std::string& frame_id) const {
  ROS_ERROR("%s: %s: %s", node_name_.c_str(), stage_.c_str(), message.c_str());
  publish(false, message, duration_s, frame_id);
}

}  // namespace kinematic_coverage::nodes
