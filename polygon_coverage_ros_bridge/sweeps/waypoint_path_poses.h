#pragma once

#include <vector>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// Default angle (radians) between the sampled poses of an in-place rotation.
constexpr double kDefaultRotationStep = 0.2;

/// The poses a robot passes through when it follows a waypoint path by turning in place
/// and driving straight: each leg from waypoint i to i + 1 is driven with the leg's
/// heading (so it sweeps the convex hull of its two end footprints), and at each waypoint
/// where the heading changes the shorter in-place rotation is sampled at most
/// `rotation_step` apart. Consecutive duplicate waypoints (within kSamePositionTolerance)
/// are skipped, so zero-length legs add nothing; a path at a single position gives that
/// position with the first waypoint's yaw. An empty path gives no poses.
/// Throws InvalidInputError for a non-finite waypoint or a rotation step that is not
/// finite and > 0.
std::vector<Pose2> waypointPathPoses(const std::vector<Pose2>& waypoints,
                                     double rotation_step = kDefaultRotationStep);

}  // namespace kinematic_coverage::core
