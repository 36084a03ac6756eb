#pragma once

#include <array>
#include <vector>

namespace kinematic_coverage::core {

/// The percentiles of the tracking error that `coverage_tool simulate` reports, as in the
/// thesis's Table 4.2 (`tracking_error_percentiles_m`; docs/REFERENCE.md, Metrics).
inline constexpr std::array<int, 9> kTrackingErrorPercentiles{1, 5, 10, 25, 50, 75, 90, 95, 99};

/// Hz: the rate at which `coverage_tool simulate` also samples its errors (the `_2hz` keys;
/// docs/REFERENCE.md, Metrics), so that sums do not scale with sim_dt and compare with the
/// thesis's sums, whose sampling it does not state.
inline constexpr double kErrorSampleRate = 2.0;

/// Summary of a robot's tracking errors (one per simulation step, metres): the thesis's
/// "trajectory error" of Tables 4.1 and 4.3 is the sum.
struct TrackingErrorStatistics {
  double sum_m = 0.0;
  double mean_m = 0.0;
  /// The value at each of kTrackingErrorPercentiles, in that order.
  std::array<double, kTrackingErrorPercentiles.size()> percentiles_m{};
};

/// Sum, mean and percentiles of `errors`. A percentile q interpolates linearly between the
/// sorted errors at ranks floor and ceil of q / 100 * (n - 1) (the common "linear"
/// definition, numpy's default). No errors give all zeros.
TrackingErrorStatistics summarizeTrackingErrors(std::vector<double> errors);

}  // namespace kinematic_coverage::core
