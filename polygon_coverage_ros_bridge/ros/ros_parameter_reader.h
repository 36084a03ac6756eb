#pragma once

#include <ros/node_handle.h>

#include <optional>
#include <string>

#include "polygon_coverage_ros_bridge/mission/mission.h"
#include "polygon_coverage_ros_bridge/parameters/planner_parameters.h"

namespace kinematic_coverage::nodes {

/// The planner parameters (docs/REFERENCE.md, Parameters) from a node's private namespace: the
/// built-in defaults (equal to config/default.yaml), overridden by each parameter that is
/// set, read and validated exactly as a mission file's keys. Throws
/// core::InvalidInputError naming the parameter for a wrong type or a value out of range.
core::PlannerParameters readPlannerParameters(const ros::NodeHandle& private_node);

/// A node-only number parameter (docs/REFERENCE.md, Parameters): `default_value` when it is
/// not set, else its value, which must be an integer or a double. Throws
/// core::InvalidInputError naming the parameter, the expected type and the type given.
double readNumberParameter(const ros::NodeHandle& node, const std::string& name,
                           double default_value);

/// A node-only true/false parameter, as readNumberParameter.
bool readFlagParameter(const ros::NodeHandle& node, const std::string& name, bool default_value);

/// A node-only string parameter, as readNumberParameter.
std::string readStringParameter(const ros::NodeHandle& node, const std::string& name,
                                const std::string& default_value);

/// A node-only `[latitude, longitude]` parameter (WGS84 degrees, two numbers): nothing when
/// it is not set. Throws core::InvalidInputError naming the parameter for another shape or
/// type (the range is the caller's to check).
std::optional<core::GeoPoint> readGeoPointParameter(const ros::NodeHandle& node,
                                                    const std::string& name);

}  // namespace kinematic_coverage::nodes
