#pragma once

#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// Waypoints closer than this (m) to the previous kept one are duplicates and dropped.
constexpr double kDuplicateWaypointDistance = 1e-9;

/// The waypoints a smoother turns at: `waypoints` without duplicates (within
/// kDuplicateWaypointDistance) and without straight interior waypoints (heading change <=
/// kStraightTurnTolerance), so that every interior point is a real corner. Both smoothing
/// strategies start from it. Throws InvalidInputError for a non-finite coordinate.
std::vector<Point2> cornerWaypoints(const std::vector<Point2>& waypoints);

}  // namespace kinematic_coverage::core
