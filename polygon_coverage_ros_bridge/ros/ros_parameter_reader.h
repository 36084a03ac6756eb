#pragma once

#include <ros/node_handle.h>

#include "polygon_coverage_ros_bridge/planner/planner_parameters.h"

namespace kinematic_coverage::nodes {

/// The planner parameters (docs/REFERENCE.md, Parameters) from a node's private namespace: the
/// built-in defaults (equal to config/default.yaml), overridden by each parameter that is
/// set, read and validated exactly as a mission file's keys. Throws
/// core::InvalidInputError naming the parameter for a wrong type or a value out of range.
core::PlannerParameters readPlannerParameters(const ros::NodeHandle& private_node);

}  // namespace kinematic_coverage::nodes
