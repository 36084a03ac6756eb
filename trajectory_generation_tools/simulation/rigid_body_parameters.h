#pragma once

namespace kinematic_coverage::core {

/// The hydrodynamic model of the dynamic vehicle (PlanarRigidBody): a small hovering
/// vehicle in surge, sway and yaw (Fossen, Handbook of Marine Craft Hydrodynamics and
/// Motion Control, 2011, Ch. 6: M nu' + C(nu) nu + D(nu) nu = tau, diagonal M and D).
/// The defaults are the BlueROV2's, identified by C.-J. Wu, "6-DoF Modelling and Control of
/// a Remotely Operated Vehicle", MSc thesis, Flinders University, 2018 (the values of the
/// OsloMet-OceanLab BlueROV2 model and of von Benzon et al., J. Mar. Sci. Eng. 10:1898,
/// 2022), and its four horizontal Blue Robotics T200 thrusters (datasheet: 4.1 kgf = 40 N
/// reverse thrust at 16 V; 45 degree vectored frame, 0.189 m yaw lever arm). They were
/// chosen before any experiment ran (docs/EXPERIMENTS.md). Added masses and damping
/// coefficients are magnitudes (>= 0): the model subtracts them where Fossen's signs say.
struct RigidBodyParameters {
  double mass = 11.5;                      ///< kg (Wu 2018)
  double added_mass_surge = 5.5;           ///< kg, -X_u' (Wu 2018)
  double added_mass_sway = 12.7;           ///< kg, -Y_v' (Wu 2018)
  double inertia_yaw = 0.16;               ///< kg m^2, I_z (Wu 2018)
  double added_inertia_yaw = 0.12;         ///< kg m^2, -N_r' (Wu 2018)
  double damping_surge_linear = 4.03;      ///< N s/m, -X_u (Wu 2018)
  double damping_sway_linear = 6.22;       ///< N s/m, -Y_v (Wu 2018)
  double damping_yaw_linear = 0.07;        ///< N m s/rad, -N_r (Wu 2018)
  double damping_surge_quadratic = 18.18;  ///< N s^2/m^2, -X_u|u| (Wu 2018)
  double damping_sway_quadratic = 21.66;   ///< N s^2/m^2, -Y_v|v| (Wu 2018)
  double damping_yaw_quadratic = 1.55;     ///< N m s^2/rad^2, -N_r|r| (Wu 2018)
  /// N: largest surge force, 4 x 40 N x cos 45 deg (T200 reverse thrust, the weaker way).
  double thrust_max = 113.0;
  /// N m: largest yaw torque, 4 x 40 N x 0.189 m.
  double yaw_torque_max = 30.0;
  /// Whether the thrusters drive sway: the vectored frame's four thrusters drive surge,
  /// sway (up to thrust_max) and yaw together, sharing their limits; false is a
  /// torpedo-like variant, sway unactuated, surge and yaw limited apart.
  bool sway_actuated = true;

  /// kg: surge inertia with added mass, m11.
  double surgeInertia() const { return mass + added_mass_surge; }
  /// kg: sway inertia with added mass, m22.
  double swayInertia() const { return mass + added_mass_sway; }
  /// kg m^2: yaw inertia with added inertia, m33.
  double yawInertia() const { return inertia_yaw + added_inertia_yaw; }
  /// N: surge damping force at surge speed u (through the water).
  double surgeDamping(double u) const {
    return (damping_surge_linear + damping_surge_quadratic * (u < 0 ? -u : u)) * u;
  }
  /// N: sway damping force at sway speed v.
  double swayDamping(double v) const {
    return (damping_sway_linear + damping_sway_quadratic * (v < 0 ? -v : v)) * v;
  }
  /// N m: yaw damping torque at yaw rate r.
  double yawDamping(double r) const {
    return (damping_yaw_linear + damping_yaw_quadratic * (r < 0 ? -r : r)) * r;
  }
};

}  // namespace kinematic_coverage::core
