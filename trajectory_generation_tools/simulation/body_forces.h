#pragma once

namespace kinematic_coverage::core {

/// The forces a controller applies to the dynamic vehicle, in the body frame.
struct BodyForces {
  double surge = 0.0;       ///< N along the heading
  double sway = 0.0;        ///< N to the left of the heading (sway_actuated only)
  double yaw_torque = 0.0;  ///< N m, counter-clockwise
};

}  // namespace kinematic_coverage::core
