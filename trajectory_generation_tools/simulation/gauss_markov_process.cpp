#include "trajectory_generation_tools/simulation/gauss_markov_process.h"

#include <cmath>

namespace kinematic_coverage::core {

GaussMarkovProcess::GaussMarkovProcess(double sigma, double time_constant,
                                       StandardNormalSource& normal)
    : sigma_(sigma), time_constant_(time_constant), value_(sigma * normal.next()) {}

void GaussMarkovProcess::advance(double duration, StandardNormalSource& normal) {
  const double decay = std::exp(-duration / time_constant_);
  value_ = decay * value_ + sigma_ * std::sqrt(1.0 - decay * decay) * normal.next();
}

}  // namespace kinematic_coverage::core
