#pragma once

#include <cstdint>

namespace kinematic_coverage::core {

/// What the simulated lake does to the robot beyond the constant current (parameters
/// current_sigma, current_time_constant, navigation_sigma, navigation_time_constant,
/// disturbance_seed; docs/REFERENCE.md). All off by default: a run is then the ideal,
/// noise-free one. Ranges are the parameter schema's.
struct DisturbanceParameters {
  /// m/s: stationary standard deviation of the current's fluctuation about (current_x,
  /// current_y), per axis; the controller does not know it.
  double current_sigma = 0.0;
  double current_time_constant = 60.0;  ///< s: correlation time of the current's fluctuation
  /// m: stationary standard deviation of the navigation solution's position error, per
  /// axis: the controller steers by the true position plus this error.
  double navigation_sigma = 0.0;
  double navigation_time_constant = 2.0;  ///< s: correlation time of the navigation error
  std::uint32_t seed = 1;                 ///< draws the same disturbance for the same seed
};

}  // namespace kinematic_coverage::core
