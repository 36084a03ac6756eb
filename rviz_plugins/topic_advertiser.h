#pragma once

#include <ros/exception.h>
#include <ros/names.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>

#include <optional>
#include <string>

namespace kinematic_coverage::rviz_plugins {

/// Advertises `Message` on `topic` (a tool's Topic property) into `*publisher`. A name that
/// is not a valid ROS name (ros::names::validate) keeps the topic advertised so far, or
/// `fallback` at start-up, so that the tool keeps publishing where the nodes listen; the
/// problem is returned for the tool to show.
template <class Message>
std::optional<std::string> advertiseTopic(ros::NodeHandle& node, const std::string& topic,
                                          const std::string& fallback, bool latch,
                                          ros::Publisher* publisher) {
  std::string problem;
  if (topic.empty()) {
    problem = "the name is empty";
  } else if (ros::names::validate(topic, problem)) {
    try {
      *publisher = node.advertise<Message>(topic, 1, latch);
      return std::nullopt;
    } catch (const ros::Exception& error) {
      problem = error.what();
    }
  }
  if (!*publisher) *publisher = node.advertise<Message>(fallback, 1, latch);
  return problem;
}

}  // namespace kinematic_coverage::rviz_plugins
