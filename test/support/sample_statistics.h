#pragma once

#include <cmath>
#include <utility>
#include <vector>

namespace kinematic_coverage::core {
namespace testing {

/// The mean and the (population) standard deviation of `values`, for tests of random
/// processes.
inline std::pair<double, double> meanAndDeviation(const std::vector<double>& values) {
  double sum = 0.0;
  for (const double value : values) sum += value;
  const double mean = sum / values.size();
  double squares = 0.0;
  for (const double value : values) squares += (value - mean) * (value - mean);
  return {mean, std::sqrt(squares / values.size())};
}

}  // namespace testing
}  // namespace kinematic_coverage::core
