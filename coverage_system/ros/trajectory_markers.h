#pragma once

#include <std_msgs/Header.h>
#include <visualization_msgs/MarkerArray.h>

#include <vector>

#include "trajectory_generation_tools/path/path_primitive.h"

namespace kinematic_coverage::nodes {

/// The smoothed path for rviz (`~markers` of smooth_trajectory_generator): straight
/// segments in grey, arcs coloured by smoothing variant (inner green, outer at the
/// bisector blue, outer at the tangent intersection magenta), and the corners that stay
/// in-place rotations as red spheres. Replaces every earlier marker of the publisher. Widths grow
/// with the path's extent; a path that would take more than MarkerScale::kPointBudget points
/// (a lake's) is drawn instead as one grey strip (namespace `trajectory`) simplified within the
/// least tolerance that keeps it to the budget, with its rotations.
visualization_msgs::MarkerArray trajectoryMarkers(const std::vector<core::PathPrimitive>& path,
                                                  const std_msgs::Header& header);

/// Where the trajectory comes nearer the walls than `wall_distance` (namespace
/// `closest_approach`): a sphere `size` metres across there and a text naming the distance;
/// to be added to trajectoryMarkers' array only then.
visualization_msgs::MarkerArray closestApproachMarkers(const core::Point2& where,
                                                       double clearance_m, double wall_distance,
                                                       const std_msgs::Header& header,
                                                       double size = 0.6);

}  // namespace kinematic_coverage::nodes
