#include "trajectory_generation_tools/simulation/standard_normal_source.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "test/support/sample_statistics.h"

namespace kinematic_coverage::core {
namespace {

using testing::meanAndDeviation;

TEST(StandardNormalSourceTest, DrawsAStandardNormalThatRepeatsForASeed) {
  StandardNormalSource source(7);
  StandardNormalSource same(7);
  StandardNormalSource other(8);
  std::vector<double> draws;
  bool differs = false;
  for (int i = 0; i < 200000; ++i) {
    draws.push_back(source.next());
    EXPECT_EQ(draws.back(), same.next());
    differs = differs || other.next() != draws.back();
  }
  EXPECT_TRUE(differs);
  const auto [mean, deviation] = meanAndDeviation(draws);
  // Five standard errors: 5 / sqrt(200000) = 0.011.
  EXPECT_NEAR(mean, 0.0, 0.011);
  EXPECT_NEAR(deviation, 1.0, 0.011);
  // The tails of a normal: 4.55 % beyond 2 sigma.
  int beyond_two = 0;
  for (const double draw : draws) beyond_two += std::abs(draw) > 2.0 ? 1 : 0;
  EXPECT_NEAR(beyond_two / 200000.0, 0.0455, 0.003);
}

}  // namespace
}  // namespace kinematic_coverage::core
