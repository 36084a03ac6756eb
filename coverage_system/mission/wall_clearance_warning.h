#pragma once

#include <optional>
#include <string>

#include "coverage_system/parameters/planner_parameters.h"

namespace kinematic_coverage::core {

/// A warning when a trajectory comes nearer the hull or a hole than `wall_distance`,
/// naming the closest approach and what let it in: a smoothing_clearance below the wall
/// distance (turns in the wall band), a gap_clearance below it (transits through narrower
/// gaps), or else the waypoints themselves. None when it keeps the distance within
/// kClearanceTolerance. `min_obstacle_clearance_m` is the trajectory's
/// (GeneratedTrajectory), which leaves out the ways into and out of the offset free area
/// from a start or goal in the wall band. Throws InvalidInputError for parameters out of
/// range.
std::optional<std::string> wallClearanceWarning(double min_obstacle_clearance_m,
                                                const PlannerParameters& parameters);

}  // namespace kinematic_coverage::core
