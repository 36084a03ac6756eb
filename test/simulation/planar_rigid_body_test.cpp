#include "trajectory_generation_tools/simulation/planar_rigid_body.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// The state after `duration` s of constant `forces`, in steps of 0.1 s as the simulator takes.
RigidBodyState run(const PlanarRigidBody& body, RigidBodyState state, const BodyForces& forces,
                   double duration) {
  const int steps = static_cast<int>(std::lround(duration / 0.1));
  for (int i = 0; i < steps; ++i) state = body.advance(state, forces, 0.1);
  return state;
}

TEST(PlanarRigidBodyTest, ReachesTheSteadySpeedWhereThrustEqualsDamping) {
  // X = d1 u + d2 u^2 at steady state: u = (-d1 + sqrt(d1^2 + 4 d2 X)) / (2 d2).
  const RigidBodyParameters p;
  const PlanarRigidBody body(p, 0.0, 0.0);
  for (const double thrust : {5.0, 20.0, p.thrust_max}) {
    const double d1 = p.damping_surge_linear;
    const double d2 = p.damping_surge_quadratic;
    const double expected = (-d1 + std::sqrt(d1 * d1 + 4.0 * d2 * thrust)) / (2.0 * d2);
    const RigidBodyState end = run(body, {}, {thrust, 0.0}, 60.0);
    EXPECT_NEAR(end.surge, expected, 1e-9 * expected) << thrust;
    EXPECT_EQ(end.sway, 0.0);
    EXPECT_EQ(end.yaw_rate, 0.0);
    EXPECT_EQ(end.pose.y, 0.0);
    EXPECT_GT(end.pose.x, 0.0);
  }
  // Forces beyond the limits are clamped: twice the largest thrust gives its speed.
  const RigidBodyState limited = run(body, {}, {2.0 * p.thrust_max, 0.0}, 60.0);
  EXPECT_DOUBLE_EQ(limited.surge, run(body, {}, {p.thrust_max, 0.0}, 60.0).surge);
}

TEST(PlanarRigidBodyTest, CoastsToRestAsTheClosedFormOfItsDampingSays) {
  // m u' = -(d1 u + d2 u^2): u(t) = d1 u0 e^(-a t) / (d1 + d2 u0 (1 - e^(-a t))), a = d1 / m,
  // and x(t) = m / d2 ln(1 + d2 u0 (1 - e^(-a t)) / d1).
  const RigidBodyParameters p;
  const PlanarRigidBody body(p, 0.0, 0.0);
  const double m = p.surgeInertia();
  const double d1 = p.damping_surge_linear;
  const double d2 = p.damping_surge_quadratic;
  const double u0 = 0.5;
  RigidBodyState state;
  state.surge = u0;
  for (const double t : {1.0, 5.0, 20.0}) {
    const RigidBodyState end = run(body, state, {}, t);
    const double w = 1.0 - std::exp(-d1 / m * t);
    EXPECT_NEAR(end.surge, d1 * u0 * (1.0 - w) / (d1 + d2 * u0 * w), 1e-9) << t;
    EXPECT_NEAR(end.pose.x, m / d2 * std::log(1.0 + d2 * u0 * w / d1), 1e-8) << t;
  }
}

TEST(PlanarRigidBodyTest, TurnsSteadilyOnTheCircleOfItsSteadyVelocities) {
  // Choose the steady state (u, r); sway then balances the centripetal term with its
  // damping, m11 u r + Y_v v + Y_vv |v| v = 0, and the forces that hold it are
  // X = D_u(u) - m22 v r and N = D_r(r) - (m11 - m22) u v. The body then drives a circle of
  // radius sqrt(u^2 + v^2) / r. The Munk moment makes such a turn unstable in open loop
  // (m22 > m11), so the yaw torque also feeds back the yaw-rate error, as the vehicle's
  // yaw-rate loop does; the feedback vanishes at the steady state.
  const RigidBodyParameters p;
  const PlanarRigidBody body(p, 0.0, 0.0);
  const double u = 0.3;
  const double r = 0.3;
  const double c = p.surgeInertia() * u * r;
  const double a = p.damping_sway_quadratic;
  const double b = p.damping_sway_linear;
  const double v = -(-b + std::sqrt(b * b + 4.0 * a * c)) / (2.0 * a);
  const double surge_force = p.surgeDamping(u) - p.swayInertia() * v * r;
  const double yaw_torque = p.yawDamping(r) - (p.surgeInertia() - p.swayInertia()) * u * v;
  const auto drive = [&](RigidBodyState state, double duration) {
    const int steps = static_cast<int>(std::lround(duration / 0.1));
    for (int i = 0; i < steps; ++i) {
      const double feedback = p.yawInertia() * 5.0 * (r - state.yaw_rate);
      state = body.advance(state, {surge_force, 0.0, yaw_torque + feedback}, 0.1);
    }
    return state;
  };
  RigidBodyState state = drive({}, 120.0);
  EXPECT_NEAR(state.surge, u, 1e-6);
  EXPECT_NEAR(state.sway, v, 1e-6);
  EXPECT_NEAR(state.yaw_rate, r, 1e-6);
  EXPECT_LT(state.sway, 0.0);  // a left turn slips to the right, outwards
  const double radius = std::hypot(u, v) / r;
  const auto centre = [&](const RigidBodyState& s) {
    const double cos_yaw = std::cos(s.pose.yaw);
    const double sin_yaw = std::sin(s.pose.yaw);
    const double along = -s.sway / s.yaw_rate;
    const double across = s.surge / s.yaw_rate;
    return Point2(s.pose.x + cos_yaw * along - sin_yaw * across,
                  s.pose.y + sin_yaw * along + cos_yaw * across);
  };
  const Point2 first_centre = centre(state);
  for (int step = 0; step < 20; ++step) {
    state = drive(state, 1.0);
    EXPECT_LT((centre(state) - first_centre).norm(), 1e-5) << step;
    EXPECT_NEAR((state.pose.position() - first_centre).norm(), radius, 1e-5) << step;
  }
  // The slip makes the circle wider than u / r, the circle of a body that does not slip.
  EXPECT_GT(radius, u / r + 0.1);
}

TEST(PlanarRigidBodyTest, DriftsWithTheCurrent) {
  const PlanarRigidBody body(RigidBodyParameters{}, 0.2, -0.1);
  RigidBodyState start;
  start.pose = {1.0, 2.0, 0.7};
  const RigidBodyState end = run(body, start, {}, 10.0);
  EXPECT_NEAR(end.pose.x, 3.0, 1e-12);
  EXPECT_NEAR(end.pose.y, 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(end.pose.yaw, 0.7);
}

/// Kinetic energy (J) of the body's motion through the water, added masses included.
double kineticEnergy(const RigidBodyParameters& p, const RigidBodyState& s) {
  return 0.5 * (p.surgeInertia() * s.surge * s.surge + p.swayInertia() * s.sway * s.sway +
                p.yawInertia() * s.yaw_rate * s.yaw_rate);
}

TEST(PlanarRigidBodyTest, WithoutForcesItGainsNoEnergy) {
  // The Coriolis and Munk terms exchange energy between surge, sway and yaw without adding
  // any (u m22 v r - v m11 u r + r (m11 - m22) u v = 0); damping only takes it away.
  const RigidBodyParameters p;
  const PlanarRigidBody body(p, 0.0, 0.0);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> speed(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    RigidBodyState state;
    state.surge = speed(rng);
    state.sway = speed(rng);
    state.yaw_rate = speed(rng);
    double energy = kineticEnergy(p, state);
    for (int step = 0; step < 100; ++step) {
      state = body.advance(state, {}, 0.1);
      const double next = kineticEnergy(p, state);
      EXPECT_LE(next, energy + 1e-12) << trial << " " << step;
      energy = next;
    }
  }
}

TEST(PlanarRigidBodyTest, UnforcedSwayAndYawHaveTheSignsOfCoriolisAndMunk) {
  // m22 v' = -m11 u r: a left turn (r > 0) ahead (u > 0) slips to the right, outwards;
  // m33 r' = (m11 - m22) u v: with m22 > m11 a body moving ahead and to the left turns right.
  const RigidBodyParameters p;
  ASSERT_GT(p.swayInertia(), p.surgeInertia());
  const PlanarRigidBody body(p, 0.0, 0.0);
  for (const double side : {1.0, -1.0}) {
    RigidBodyState turning;
    turning.surge = 0.5;
    turning.yaw_rate = 0.5 * side;
    EXPECT_LT(side * body.advance(turning, {}, 0.01).sway, 0.0) << side;
    RigidBodyState slipping;
    slipping.surge = 0.5;
    slipping.sway = 0.2 * side;
    EXPECT_LT(side * body.advance(slipping, {}, 0.01).yaw_rate, 0.0) << side;
  }
}

TEST(PlanarRigidBodyTest, HalvingTheStepCutsTheIntegrationErrorSixteenfold) {
  // The classical Runge-Kutta method is of fourth order: under a constant input within the
  // thrusters' limits, halving the step divides the error by about 2^4 (at steps like the
  // simulator's, well below those at which the stiff yaw dynamics make it unstable).
  const RigidBodyParameters p;
  const PlanarRigidBody body(p, 0.0, 0.0);
  RigidBodyState start;
  start.surge = 0.4;
  start.sway = -0.1;
  start.yaw_rate = 0.6;
  const BodyForces forces{20.0, 5.0, 1.0};
  ASSERT_DOUBLE_EQ(body.limited(forces).surge, forces.surge);
  const RigidBodyState exact = body.advance(start, forces, 5.0, 1e-4);
  const auto error = [&](double step) {
    const RigidBodyState end = body.advance(start, forces, 5.0, step);
    return std::hypot(end.pose.x - exact.pose.x, end.pose.y - exact.pose.y);
  };
  const double ratio = error(0.025) / error(0.0125);
  EXPECT_GT(ratio, 12.0);
  EXPECT_LT(ratio, 20.0);
}

TEST(PlanarRigidBodyTest, TheVectoredThrustersDriveSwayAndTheTorpedoVariantDoesNot) {
  // Y = d1 v + d2 v^2 at steady sway; without sway actuation the sway force is not applied.
  RigidBodyParameters p;
  const double force = 20.0;
  const double d1 = p.damping_sway_linear;
  const double d2 = p.damping_sway_quadratic;
  const double expected = (-d1 + std::sqrt(d1 * d1 + 4.0 * d2 * force)) / (2.0 * d2);
  const RigidBodyState actuated = run(PlanarRigidBody(p, 0.0, 0.0), {}, {0.0, force, 0.0}, 60.0);
  EXPECT_NEAR(actuated.sway, expected, 1e-9);
  EXPECT_GT(actuated.pose.y, 0.0);
  p.sway_actuated = false;
  const RigidBodyState torpedo = run(PlanarRigidBody(p, 0.0, 0.0), {}, {0.0, force, 0.0}, 60.0);
  EXPECT_EQ(torpedo.sway, 0.0);
  EXPECT_EQ(torpedo.pose.y, 0.0);
}

TEST(PlanarRigidBodyTest, AppliedForcesStayWithinTheThrustersLimits) {
  // Sway actuated: every thruster within its limit, and a demand they can meet met exactly;
  // the torpedo variant: surge and yaw clamped apart, no sway force.
  RigidBodyParameters p;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> share(-2.0, 2.0);
  const VectoredThrustAllocation allocation(p.thrust_max, p.yaw_torque_max);
  for (int trial = 0; trial < 1000; ++trial) {
    const BodyForces demand{share(rng) * p.thrust_max, share(rng) * p.thrust_max,
                            share(rng) * p.yaw_torque_max};
    p.sway_actuated = true;
    const BodyForces applied = PlanarRigidBody(p, 0.0, 0.0).limited(demand);
    for (const double thrust : allocation.thrusterShares(applied)) {
      EXPECT_LE(std::abs(thrust), 1.0 + 1e-12) << trial;
    }
    p.sway_actuated = false;
    const BodyForces torpedo = PlanarRigidBody(p, 0.0, 0.0).limited(demand);
    EXPECT_LE(std::abs(torpedo.surge), p.thrust_max);
    EXPECT_LE(std::abs(torpedo.yaw_torque), p.yaw_torque_max);
    EXPECT_EQ(torpedo.sway, 0.0);
  }
}

TEST(PlanarRigidBodyTest, WrapsTheHeading) {
  const PlanarRigidBody body(RigidBodyParameters{}, 0.0, 0.0);
  RigidBodyState start;
  start.pose.yaw = M_PI - 0.01;
  start.yaw_rate = 0.5;
  const RigidBodyState end = body.advance(start, {0.0, 0.0}, 0.1);
  EXPECT_LT(end.pose.yaw, 0.0);
  EXPECT_GT(end.pose.yaw, -M_PI);
}

}  // namespace
}  // namespace kinematic_coverage::core
