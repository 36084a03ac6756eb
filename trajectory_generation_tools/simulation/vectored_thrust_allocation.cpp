#include "trajectory_generation_tools/simulation/vectored_thrust_allocation.h"

#include <algorithm>

namespace kinematic_coverage::core {
namespace {

/// The sign patterns (surge, sway, yaw) of the four thrusters' contributions.
constexpr std::array<std::array<double, 3>, 4> kSigns = {{
    {{1.0, 1.0, 1.0}},
    {{1.0, -1.0, -1.0}},
    {{-1.0, 1.0, -1.0}},
    {{-1.0, -1.0, 1.0}},
}};

/// The span of s_i . z that the thrusters meet: every share within [-1, 1].
constexpr double kFeasibleSpan = 2.0;

}  // namespace

VectoredThrustAllocation::VectoredThrustAllocation(double thrust_max, double yaw_torque_max)
    : thrust_max_(thrust_max), yaw_torque_max_(yaw_torque_max) {}

std::array<double, 4> VectoredThrustAllocation::thrusterShares(const BodyForces& demand) const {
  const std::array<double, 3> z = {demand.surge / thrust_max_, demand.sway / thrust_max_,
                                   demand.yaw_torque / yaw_torque_max_};
  std::array<double, 4> shares{};
  for (std::size_t i = 0; i < shares.size(); ++i) {
    shares[i] = kSigns[i][0] * z[0] + kSigns[i][1] * z[1] + kSigns[i][2] * z[2];
  }
  const auto [low, high] = std::minmax_element(shares.begin(), shares.end());
  const double lambda = -0.5 * (*low + *high);
  for (double& share : shares) share += lambda;
  return shares;
}

BodyForces VectoredThrustAllocation::forcesOf(const std::array<double, 4>& shares) const {
  // Each thruster at its limit gives a quarter of the frame's largest force and torque.
  BodyForces forces;
  for (std::size_t i = 0; i < shares.size(); ++i) {
    forces.surge += 0.25 * thrust_max_ * kSigns[i][0] * shares[i];
    forces.sway += 0.25 * thrust_max_ * kSigns[i][1] * shares[i];
    forces.yaw_torque += 0.25 * yaw_torque_max_ * kSigns[i][2] * shares[i];
  }
  return forces;
}

BodyForces VectoredThrustAllocation::achievable(const BodyForces& demand) const {
  const std::array<double, 4> shares = thrusterShares(demand);
  const auto [low, high] = std::minmax_element(shares.begin(), shares.end());
  const double span = *high - *low;
  if (span <= kFeasibleSpan) return demand;
  const double scale = kFeasibleSpan / span;
  return {scale * demand.surge, scale * demand.sway, scale * demand.yaw_torque};
}

}  // namespace kinematic_coverage::core
