#pragma once

#include <array>

#include "trajectory_generation_tools/simulation/body_forces.h"

namespace kinematic_coverage::core {

/// Thrust allocation of the vectored frame (sway_actuated: true): four horizontal thrusters
/// at 45 degrees, as on the BlueROV2, driving surge, sway and yaw together (Fossen, Handbook
/// of Marine Craft Hydrodynamics and Motion Control, 2nd ed. 2021, Ch. 11, thrust
/// allocation for an overactuated craft).
///
/// In shares of one thruster's limit, and with the demand normalised as z = (X / thrust_max,
/// Y / thrust_max, N / yaw_torque_max) (each thruster gives thrust_max / 4 of surge or sway
/// and yaw_torque_max / 4 of torque at its limit), thruster i's thrust is
///   f_i = s_i . z + lambda,   s_i in {(+,+,+), (+,-,-), (-,+,-), (-,-,+)},
/// the frame's configuration inverted, plus lambda of its null space (all four pushing
/// against each other, no net force or torque), chosen to make the largest |f_i| least:
/// lambda = -(max + min) / 2 of s_i . z. A demand whose s_i . z span more than 2 cannot be
/// met; it is scaled down whole to the largest that can, so that its direction is kept
/// (surge, sway and yaw in the proportions the controller asked for).
class VectoredThrustAllocation {
 public:
  /// thrust_max: N of surge (and of sway) at the thrusters' limits; yaw_torque_max: N m.
  VectoredThrustAllocation(double thrust_max, double yaw_torque_max);

  /// The forces the thrusters give for `demand`: the demand itself where they can, else the
  /// demand scaled down whole to their limits.
  BodyForces achievable(const BodyForces& demand) const;

  /// Each thruster's thrust for `demand` as a share of its limit (min-max allocation; a
  /// share beyond 1 in size where the demand cannot be met).
  std::array<double, 4> thrusterShares(const BodyForces& demand) const;

  /// The forces and torque of thrusts given as shares of each thruster's limit.
  BodyForces forcesOf(const std::array<double, 4>& shares) const;

 private:
  double thrust_max_;
  double yaw_torque_max_;
};

}  // namespace kinematic_coverage::core
