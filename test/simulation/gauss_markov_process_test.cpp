#include "trajectory_generation_tools/simulation/gauss_markov_process.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "test/support/sample_statistics.h"
#include "trajectory_generation_tools/simulation/standard_normal_source.h"

namespace kinematic_coverage::core {
namespace {

using testing::meanAndDeviation;

TEST(GaussMarkovProcessTest, IsStationaryWithTheGivenDeviationAndCorrelationTime) {
  // sigma 0.3, T 5 s, sampled every 0.5 s: the lag-one correlation is exp(-0.1).
  StandardNormalSource normal(3);
  GaussMarkovProcess process(0.3, 5.0, normal);
  std::vector<double> values;
  for (int i = 0; i < 400000; ++i) {
    values.push_back(process.value());
    process.advance(0.5, normal);
  }
  const auto [mean, deviation] = meanAndDeviation(values);
  // About 400000 * 0.5 / (2 * 5) = 20000 independent samples: a standard error of
  // 0.3 / sqrt(20000) = 0.002 on the mean.
  EXPECT_NEAR(mean, 0.0, 0.01);
  EXPECT_NEAR(deviation, 0.3, 0.01);
  double lagged = 0.0;
  for (std::size_t i = 1; i < values.size(); ++i) lagged += values[i] * values[i - 1];
  EXPECT_NEAR(lagged / (values.size() - 1) / (deviation * deviation), std::exp(-0.1), 0.01);
}

TEST(GaussMarkovProcessTest, TheStepDoesNotChangeTheStatistics) {
  // The exact discretization: steps of 0.1 s or of 2 s give the same deviation.
  for (const double step : {0.1, 2.0}) {
    StandardNormalSource normal(5);
    GaussMarkovProcess process(1.0, 1.0, normal);
    std::vector<double> values;
    for (int i = 0; i < 200000; ++i) {
      process.advance(step, normal);
      values.push_back(process.value());
    }
    EXPECT_NEAR(meanAndDeviation(values).second, 1.0, 0.03) << step;
  }
}

TEST(GaussMarkovProcessTest, AZeroDeviationStaysAtZero) {
  StandardNormalSource normal(1);
  GaussMarkovProcess process(0.0, 10.0, normal);
  for (int i = 0; i < 100; ++i) {
    EXPECT_EQ(process.value(), 0.0);
    process.advance(0.1, normal);
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
