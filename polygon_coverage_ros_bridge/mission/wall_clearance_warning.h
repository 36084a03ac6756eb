#pragma once

#include <optional>
#include <string>

#include "polygon_coverage_ros_bridge/parameters/planner_parameters.h"

namespace kinematic_coverage::core {

/// A warning when a smoothed trajectory comes nearer the hull or a hole than
/// `wall_distance` because the user let its turns into the wall band (a smoothing_clearance
/// below the wall distance), naming the closest approach; none when it keeps the distance
/// within kClearanceTolerance, or when it is unsmoothed or the clearance is the wall
/// distance (then only a gap the planner warns of comes nearer). `min_obstacle_clearance_m`
/// is the trajectory's (GeneratedTrajectory). Throws InvalidInputError for parameters out of
/// range.
std::optional<std::string> wallClearanceWarning(double min_obstacle_clearance_m,
                                                const PlannerParameters& parameters);

}  // namespace kinematic_coverage::core
