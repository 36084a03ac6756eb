#pragma once

#include <ros/node_handle.h>

#include <optional>
#include <string>

#include "coverage_system/mission/mission.h"
#include "coverage_system/parameters/planner_parameters.h"

namespace kinematic_coverage::nodes {

/// The planner parameters (docs/REFERENCE.md, Parameters) of a node: the built-in defaults
/// (equal to config/default.yaml), then the parameter file named by `~config` and the
/// parameter keys of the mission file named by `~mission` (YAML or GeoJSON), each when set,
/// then each parameter set in the node's private namespace, read and validated exactly as a
/// mission file's keys. The launch files set the two paths only, so the parameter server
/// holds what a user changes, not every parameter in every node. Throws
/// core::InvalidInputError naming the parameter or file for a wrong type, a value out of
/// range or a file that cannot be read.
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
