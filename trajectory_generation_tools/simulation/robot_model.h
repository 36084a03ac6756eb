#pragma once

#include "polygon_coverage_ros_bridge/base/vehicle_limits.h"
#include "trajectory_generation_tools/simulation/disturbance_parameters.h"
#include "trajectory_generation_tools/simulation/rigid_body_parameters.h"

namespace kinematic_coverage::core {

/// Which vehicle the simulator drives (parameter `vehicle_model`).
enum class VehicleModel {
  kDynamic,    ///< a rigid body with inertia and damping (PlanarRigidBody), the default
  kKinematic,  ///< the first model: surge speed and yaw rate follow their commands at once
};

/// How the simulated robot tracks a trajectory (parameter `controller`).
enum class TrackingController {
  kTimed,       ///< feedforward plus PD on the timed reference p_d(t), the default
  kSetpoint,    ///< the first follower: homing on each pose in turn
  kPoseStream,  ///< as kTimed, pose i released at i / pose_rate
  kLos,         ///< line-of-sight guidance on the pose polyline
};

/// True for the controllers that follow the trajectory's times (its t column): timed, and
/// los for its speeds; setpoint and pose_stream follow the poses alone.
inline bool usesTrajectoryTimes(TrackingController controller) {
  return controller == TrackingController::kTimed || controller == TrackingController::kLos;
}

/// The simulated robot of `coverage_tool simulate` and auv_simulator (TrajectoryFollower,
/// docs/REFERENCE.md, Parameters): its vehicle, limits, controllers' gains and tolerances,
/// the water current, its disturbances and the simulation step. Its ranges are
/// parameter schema's (checkParameters).
struct RobotModel {
  VehicleModel vehicle_model = VehicleModel::kDynamic;
  VehicleLimits vehicle;     ///< v_max, a_max and yaw_rate_max bound the commands
  RigidBodyParameters body;  ///< the dynamic vehicle's mass, damping and thrusters
  TrackingController controller = TrackingController::kTimed;
  bool braking = true;                      ///< kSetpoint: brake in time to stop at a turn
  double tracking_natural_frequency = 1.0;  ///< rad/s: kTimed and kPoseStream's wn
  double tracking_damping = 1.0;            ///< kTimed and kPoseStream's zeta
  double pose_rate = 1.0;                   ///< Hz: kPoseStream's release rate
  double los_lookahead = 0.0;               ///< m: kLos's look-ahead; 0: the turning radius
  double yaw_gain = 5.0;                    ///< 1/s: yaw-rate command per rad of heading error
  double position_gain = 1.5;               ///< 1/s: surge-speed command per m to the target
  double surge_loop_gain = 5.0;             ///< 1/s: dynamic vehicle's surge-speed loop bandwidth
  double yaw_rate_loop_gain = 10.0;         ///< 1/s: dynamic vehicle's yaw-rate loop bandwidth
  double position_tolerance = 0.05;         ///< m: a position target counts as reached within it
  double yaw_tolerance = 0.05;              ///< rad: a turn-in-place target is reached within it
  double current_x = 0.0;                   ///< m/s: constant water current along x
  double current_y = 0.0;                   ///< m/s: constant water current along y
  DisturbanceParameters disturbance;        ///< the current's fluctuation and the navigation error
  double sim_dt = 0.1;                      ///< s: simulation time step
  double sim_time_limit = 36000.0;          ///< s: simulated time after which a run gives up
};

}  // namespace kinematic_coverage::core
