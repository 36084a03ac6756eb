#pragma once

#include <std_msgs/Header.h>
#include <visualization_msgs/MarkerArray.h>

#include <vector>

#include "trajectory_generation_tools/path/path_primitive.h"

namespace kinematic_coverage::nodes {

/// The smoothed path for rviz (`~markers` of smooth_trajectory_generator): straight
/// segments in grey, arcs coloured by smoothing variant (inner green, outer at the
/// bisector blue, outer at the tangent intersection magenta), and the corners that stay
/// in-place rotations as red spheres. Replaces every earlier marker of the publisher.
visualization_msgs::MarkerArray trajectoryMarkers(const std::vector<core::PathPrimitive>& path,
                                                  const std_msgs::Header& header);

/// Where the trajectory comes nearer the walls than `wall_distance` (namespace
/// `closest_approach`): a sphere there and a text naming the distance; to be added to
/// trajectoryMarkers' array only then.
visualization_msgs::MarkerArray closestApproachMarkers(const core::Point2& where,
                                                       double clearance_m, double wall_distance,
                                                       const std_msgs::Header& header);

}  // namespace kinematic_coverage::nodes
