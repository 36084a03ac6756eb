#pragma once

#include <algorithm>

namespace kinematic_coverage::core {

/// What the robot can do (docs/REFERENCE.md, Parameters): the limits every stage that
/// costs, smooths, times or simulates motion reads, so that they all model one robot.
struct VehicleLimits {
  double v_max = 0.5;           ///< m/s, highest surge speed
  double a_max = 0.2;           ///< m/s^2, highest acceleration and deceleration
  double yaw_rate_max = 0.5;    ///< rad/s, highest turn rate
  double turning_radius = 1.0;  ///< m, the radius the smoothed path's arcs prefer

  /// The highest speed on an arc of `radius` (m/s): the yaw rate v / r bounds it.
  double arcSpeed(double radius) const { return std::min(v_max, yaw_rate_max * radius); }
};

}  // namespace kinematic_coverage::core
