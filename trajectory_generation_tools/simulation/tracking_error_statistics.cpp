#include "trajectory_generation_tools/simulation/tracking_error_statistics.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace kinematic_coverage::core {

TrackingErrorStatistics summarizeTrackingErrors(std::vector<double> errors) {
  TrackingErrorStatistics statistics;
  if (errors.empty()) return statistics;
  std::sort(errors.begin(), errors.end());
  statistics.sum_m = std::accumulate(errors.begin(), errors.end(), 0.0);
  statistics.mean_m = statistics.sum_m / static_cast<double>(errors.size());
  const double last_rank = static_cast<double>(errors.size() - 1);
  for (std::size_t i = 0; i < kTrackingErrorPercentiles.size(); ++i) {
    const double rank = kTrackingErrorPercentiles[i] / 100.0 * last_rank;
    const std::size_t below = static_cast<std::size_t>(std::floor(rank));
    const std::size_t above = std::min(below + 1, errors.size() - 1);
    const double fraction = rank - static_cast<double>(below);
    statistics.percentiles_m[i] = errors[below] + fraction * (errors[above] - errors[below]);
  }
  return statistics;
}

}  // namespace kinematic_coverage::core
