#pragma once

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/simulation/body_forces.h"
#include "trajectory_generation_tools/simulation/rigid_body_parameters.h"
#include "trajectory_generation_tools/simulation/vectored_thrust_allocation.h"

namespace kinematic_coverage::core {

/// Where a rigid body is and how it moves through the water.
struct RigidBodyState {
  Pose2 pose;             ///< position (m) and heading (rad) in the world frame
  double surge = 0.0;     ///< u, m/s through the water along the heading
  double sway = 0.0;      ///< v, m/s through the water to the left of the heading
  double yaw_rate = 0.0;  ///< r, rad/s
};

/// A planar rigid body in surge, sway and yaw, the dynamic vehicle of the simulator
/// (vehicle_model: dynamic). Its equations of motion, for velocities relative to the
/// water nu = (u, v, r) and a constant, irrotational current V_c (Fossen 2011, its
/// relative-velocity form for such a current):
///   m11 u' = X + m22 v r - D_u(u)
///   m22 v' = Y - m11 u r - D_v(v)            (Y = 0 where sway is not actuated)
///   m33 r' = N + (m11 - m22) u v - D_r(r)    (the Munk moment)
///   (x, y)' = R(psi) (u, v) + V_c,  psi' = r
/// with D_*(s) = (d_linear + d_quadratic |s|) s. It is integrated with the classical
/// Runge-Kutta method in fixed steps of at most kIntegrationStep.
class PlanarRigidBody {
 public:
  /// s: the longest integration step; a simulation step is cut into equal steps no longer.
  static constexpr double kIntegrationStep = 0.01;

  /// A body with `parameters` in a current of (current_x, current_y) m/s.
  PlanarRigidBody(const RigidBodyParameters& parameters, double current_x, double current_y);

  /// Sets the current (m/s) that later advances see, for a current that varies in time.
  void setCurrent(double current_x, double current_y);

  /// The state after `duration` s under constant `forces` (limited first), starting from
  /// `state`, in equal steps of at most `max_step` s; the heading wrapped into (-pi, pi].
  RigidBodyState advance(const RigidBodyState& state, const BodyForces& forces, double duration,
                         double max_step = kIntegrationStep) const;

  /// The equations above solved for the forces (inverse dynamics): those that give the
  /// body in `state` the world-frame acceleration `acceleration` (m/s^2) and the yaw
  /// acceleration `yaw_acceleration` (rad/s^2), its damping taken at the velocities of
  /// `damped` (its pose ignored), e.g. a reference's, fed forward by a controller.
  BodyForces forcesFor(const RigidBodyState& state, const Point2& acceleration,
                       double yaw_acceleration, const RigidBodyState& damped) const;

  /// What the thrusters give of `forces`: with sway actuated, the vectored frame's
  /// achievable forces (VectoredThrustAllocation); without, no sway force, surge clamped to
  /// +-thrust_max and yaw torque to +-yaw_torque_max apart.
  BodyForces limited(const BodyForces& forces) const;

  const RigidBodyParameters& parameters() const { return parameters_; }

 private:
  /// The time derivative of (x, y, psi, u, v, r) under `forces`.
  void derivative(const double* s, const BodyForces& forces, double* ds) const;

  RigidBodyParameters parameters_;
  VectoredThrustAllocation allocation_;
  double current_x_ = 0.0;
  double current_y_ = 0.0;
};

}  // namespace kinematic_coverage::core
