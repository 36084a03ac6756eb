#include "trajectory_generation_tools/simulation/planar_rigid_body.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// The state vector (x, y, psi, u, v, r).
using StateVector = std::array<double, 6>;

}  // namespace

PlanarRigidBody::PlanarRigidBody(const RigidBodyParameters& parameters, double current_x,
                                 double current_y)
    : parameters_(parameters),
      allocation_(parameters.thrust_max, parameters.yaw_torque_max),
      current_x_(current_x),
      current_y_(current_y) {}

void PlanarRigidBody::setCurrent(double current_x, double current_y) {
  current_x_ = current_x;
  current_y_ = current_y;
}

BodyForces PlanarRigidBody::forcesFor(const RigidBodyState& state, const Point2& acceleration,
                                      double yaw_acceleration, const RigidBodyState& damped) const {
  // In the body frame, nu' = R^T p'' - S(r) nu.
  const RigidBodyParameters& b = parameters_;
  const double c = std::cos(state.pose.yaw);
  const double s = std::sin(state.pose.yaw);
  const double u = state.surge;
  const double v = state.sway;
  const double r = state.yaw_rate;
  const Point2& a = acceleration;
  BodyForces forces;
  forces.surge = b.surgeInertia() * (c * a.x() + s * a.y() + r * v) - b.swayInertia() * v * r +
                 b.surgeDamping(damped.surge);
  forces.sway = b.swayInertia() * (-s * a.x() + c * a.y() - r * u) + b.surgeInertia() * u * r +
                b.swayDamping(damped.sway);
  forces.yaw_torque = b.yawInertia() * yaw_acceleration + b.yawDamping(damped.yaw_rate) -
                      (b.surgeInertia() - b.swayInertia()) * u * v;
  return forces;
}

BodyForces PlanarRigidBody::limited(const BodyForces& forces) const {
  if (parameters_.sway_actuated) return allocation_.achievable(forces);
  return {std::clamp(forces.surge, -parameters_.thrust_max, parameters_.thrust_max), 0.0,
          std::clamp(forces.yaw_torque, -parameters_.yaw_torque_max, parameters_.yaw_torque_max)};
}

void PlanarRigidBody::derivative(const double* s, const BodyForces& forces, double* ds) const {
  const RigidBodyParameters& p = parameters_;
  const double psi = s[2];
  const double u = s[3];
  const double v = s[4];
  const double r = s[5];
  const double m11 = p.surgeInertia();
  const double m22 = p.swayInertia();
  ds[0] = std::cos(psi) * u - std::sin(psi) * v + current_x_;
  ds[1] = std::sin(psi) * u + std::cos(psi) * v + current_y_;
  ds[2] = r;
  ds[3] = (forces.surge + m22 * v * r - p.surgeDamping(u)) / m11;
  ds[4] = (forces.sway - m11 * u * r - p.swayDamping(v)) / m22;
  ds[5] = (forces.yaw_torque + (m11 - m22) * u * v - p.yawDamping(r)) / p.yawInertia();
}

RigidBodyState PlanarRigidBody::advance(const RigidBodyState& state, const BodyForces& forces,
                                        double duration, double max_step) const {
  const BodyForces applied = limited(forces);
  const int steps = std::max(1, static_cast<int>(std::ceil(duration / max_step - 1e-9)));
  const double h = duration / steps;
  StateVector s{state.pose.x, state.pose.y, state.pose.yaw,
                state.surge,  state.sway,   state.yaw_rate};
  StateVector k1, k2, k3, k4, stage;
  const auto at = [&](const StateVector& k, double factor) {
    for (std::size_t i = 0; i < s.size(); ++i) stage[i] = s[i] + factor * k[i];
    return stage.data();
  };
  for (int step = 0; step < steps; ++step) {
    derivative(s.data(), applied, k1.data());
    derivative(at(k1, h / 2), applied, k2.data());
    derivative(at(k2, h / 2), applied, k3.data());
    derivative(at(k3, h), applied, k4.data());
    for (std::size_t i = 0; i < s.size(); ++i) {
      s[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
  }
  RigidBodyState next;
  next.pose = {s[0], s[1], wrapAngle(s[2])};
  next.surge = s[3];
  next.sway = s[4];
  next.yaw_rate = s[5];
  return next;
}

}  // namespace kinematic_coverage::core
