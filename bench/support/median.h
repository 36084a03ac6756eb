#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace kinematic_coverage::bench {

/// The median of the values (the mean of the middle two for an even count; 0 for none):
/// the per-family figure of the benchmark tables.
inline double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace kinematic_coverage::bench
