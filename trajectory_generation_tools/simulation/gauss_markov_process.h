#pragma once

#include "trajectory_generation_tools/simulation/standard_normal_source.h"

namespace kinematic_coverage::core {

/// A first-order Gauss-Markov process, x' = -x / T + w with white noise w: the model of a
/// slowly varying ocean current (Fossen, "Handbook of Marine Craft Hydrodynamics and Motion
/// Control", Wiley 2011, Section 8.3, V_c' + mu V_c = w with mu = 1 / T; the model of the
/// UUV Simulator's current plugin) and of a navigation solution's correlated position
/// error. Stationary from the start: zero mean, standard deviation `sigma`, correlation
/// exp(-|dt| / T).
class GaussMarkovProcess {
 public:
  /// A process with stationary standard deviation `sigma` (>= 0) and correlation time
  /// `time_constant` (> 0; ranges checked where they were read), its first value drawn
  /// from `normal`.
  GaussMarkovProcess(double sigma, double time_constant, StandardNormalSource& normal);

  /// Advances the process by `duration` s with the exact discretization
  /// x <- exp(-dt / T) x + sigma sqrt(1 - exp(-2 dt / T)) n, n ~ N(0, 1): the same
  /// statistics whatever the step.
  void advance(double duration, StandardNormalSource& normal);

  double value() const { return value_; }

 private:
  double sigma_;
  double time_constant_;
  double value_;
};

}  // namespace kinematic_coverage::core
