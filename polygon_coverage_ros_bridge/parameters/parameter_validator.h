#pragma once

#include "polygon_coverage_ros_bridge/parameters/planner_parameters.h"

namespace kinematic_coverage::core {

/// Checks planner parameters against their ranges (docs/REFERENCE.md, Parameters): turning_radius,
/// sensor_distance, v_max, a_max, yaw_rate_max, the sampling distances and angle,
/// lateral_footprint and alpha > 0; wall_distance >= 0; lateral_overlap in [0, 1);
/// lateral_fov and onward_fov in (0, pi); every number finite; every name-valued
/// parameter one of its values. The robot model's yaw_gain, position_gain,
/// position_tolerance, sim_dt and sim_time_limit > 0, yaw_tolerance in (0, pi), the
/// current finite; the dynamic vehicle's mass, inertia_yaw, thrust_max, yaw_torque_max and
/// loop gains > 0, its added masses and damping >= 0; and yaw_gain, surge_loop_gain and
/// yaw_rate_loop_gain times sim_dt <= 1.
class ParameterValidator {
 public:
  /// Throws InvalidInputError naming the first parameter out of range, its value and the
  /// allowed range, e.g. "lateral_overlap = 1 is out of range: it must be in [0, 1)".
  void validate(const PlannerParameters& parameters) const;
};

}  // namespace kinematic_coverage::core
