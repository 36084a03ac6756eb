#pragma once

#include "polygon_coverage_ros_bridge/base/vehicle_limits.h"

namespace kinematic_coverage::core {

/// The simulated robot of `coverage_tool simulate` and auv_simulator (TrajectoryFollower,
/// docs/REFERENCE.md, Parameters): its limits, its controllers' gains and tolerances, the
/// water current and the simulation step. Its ranges are ParameterValidator's.
struct RobotModel {
  VehicleLimits vehicle;             ///< v_max, a_max and yaw_rate_max bound the controllers
  double yaw_gain = 5.0;             ///< 1/s: yaw-rate command per rad of heading error
  double position_gain = 1.5;        ///< 1/s: surge-speed command per m to the target
  double position_tolerance = 0.05;  ///< m: a position target counts as reached within it
  double yaw_tolerance = 0.05;       ///< rad: a turn-in-place target is reached within it
  double current_x = 0.0;            ///< m/s: constant water current along x
  double current_y = 0.0;            ///< m/s: constant water current along y
  double sim_dt = 0.1;               ///< s: simulation time step
  double sim_time_limit = 36000.0;   ///< s: simulated time after which a run gives up
};

}  // namespace kinematic_coverage::core
