#include "trajectory_generation_tools/simulation/tracking_error_statistics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace kinematic_coverage::core {
namespace {

TEST(TrackingErrorStatisticsTest, SumMeanAndPercentilesOfKnownErrors) {
  // 0, 0.01, ..., 1.00 shuffled: the q-th percentile is q / 100 m exactly.
  std::vector<double> errors;
  for (int i = 0; i <= 100; ++i) errors.push_back(i / 100.0);
  std::shuffle(errors.begin(), errors.end(), std::mt19937(7));
  const TrackingErrorStatistics statistics = summarizeTrackingErrors(errors);
  EXPECT_NEAR(statistics.sum_m, 50.5, 1e-9);
  EXPECT_NEAR(statistics.mean_m, 0.5, 1e-12);
  for (std::size_t i = 0; i < kTrackingErrorPercentiles.size(); ++i) {
    EXPECT_NEAR(statistics.percentiles_m[i], kTrackingErrorPercentiles[i] / 100.0, 1e-12)
        << kTrackingErrorPercentiles[i];
  }
}

TEST(TrackingErrorStatisticsTest, PercentilesInterpolateBetweenRanks) {
  // Ranks 0..3 hold 0, 1, 2, 10: the 50th percentile lies halfway between 1 and 2, the 99th
  // at 2.97 of the way, i.e. 2 + 0.97 * 8.
  const TrackingErrorStatistics statistics = summarizeTrackingErrors({10.0, 0.0, 2.0, 1.0});
  EXPECT_DOUBLE_EQ(statistics.percentiles_m[4], 1.5);
  EXPECT_NEAR(statistics.percentiles_m[8], 2.0 + 0.97 * 8.0, 1e-12);
  EXPECT_DOUBLE_EQ(statistics.percentiles_m[0], 0.03);
  // Non-decreasing in q.
  EXPECT_TRUE(std::is_sorted(statistics.percentiles_m.begin(), statistics.percentiles_m.end()));
}

TEST(TrackingErrorStatisticsTest, NoErrorsGiveZeros) {
  const TrackingErrorStatistics statistics = summarizeTrackingErrors({});
  EXPECT_EQ(statistics.sum_m, 0.0);
  EXPECT_EQ(statistics.mean_m, 0.0);
  for (const double value : statistics.percentiles_m) EXPECT_EQ(value, 0.0);
}

}  // namespace
}  // namespace kinematic_coverage::core
