#pragma once

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// One corner A, B, C of a waypoint path as Algorithm 1 sees it: the robot comes from A,
/// turns at B and heads for C. A is a waypoint or, when the previous corner was smoothed,
/// the end of that smoothing (thesis 3.2: "a new arc begins no sooner than the previous
/// smoothing ends"), so a smoothing may start anywhere on [A, B] but not before A.
struct Corner {
  Point2 a = Point2::Zero();  ///< where the smoothing may begin at the earliest
  Point2 b = Point2::Zero();  ///< the corner waypoint
  Point2 c = Point2::Zero();  ///< the next waypoint: the smoothing ends on [B, C]
  double radius = 1.0;        ///< turning radius r of every arc, > 0
  /// Unit direction of travel into B. Zero: taken from A to B. Needed when A == B (the
  /// previous smoothing ended exactly at B), where A gives no direction.
  Point2 incoming = Point2::Zero();
};

}  // namespace kinematic_coverage::core
