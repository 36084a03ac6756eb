#include "trajectory_generation_tools/simulation/environment_disturbance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "test/support/sample_statistics.h"

namespace kinematic_coverage::core {
namespace {

using testing::meanAndDeviation;

TEST(EnvironmentDisturbanceTest, IsTheMeanCurrentAndNoErrorWhenOff) {
  EnvironmentDisturbance calm(DisturbanceParameters{}, 0.2, -0.1);
  for (int i = 0; i < 100; ++i) {
    EXPECT_EQ(calm.current(), Point2(0.2, -0.1));
    EXPECT_EQ(calm.navigationError(), Point2(0.0, 0.0));
    calm.advance(0.1);
  }
}

TEST(EnvironmentDisturbanceTest, FluctuatesAboutTheMeanCurrent) {
  DisturbanceParameters parameters;
  parameters.current_sigma = 0.05;
  parameters.current_time_constant = 10.0;
  parameters.navigation_sigma = 0.2;
  parameters.navigation_time_constant = 1.0;
  EnvironmentDisturbance lake(parameters, 0.2, -0.1);
  std::vector<double> current_x;
  std::vector<double> current_y;
  std::vector<double> error_x;
  for (int i = 0; i < 200000; ++i) {
    current_x.push_back(lake.current().x());
    current_y.push_back(lake.current().y());
    error_x.push_back(lake.navigationError().x());
    lake.advance(1.0);
  }
  EXPECT_NEAR(meanAndDeviation(current_x).first, 0.2, 0.005);
  EXPECT_NEAR(meanAndDeviation(current_y).first, -0.1, 0.005);
  EXPECT_NEAR(meanAndDeviation(current_x).second, 0.05, 0.005);
  EXPECT_NEAR(meanAndDeviation(error_x).second, 0.2, 0.01);
}

TEST(EnvironmentDisturbanceTest, KnowsWhichLakeItIs) {
  DisturbanceParameters parameters;
  parameters.current_sigma = 0.02;
  parameters.navigation_sigma = 0.1;
  EnvironmentDisturbance lake(parameters, 0.2, -0.1);
  lake.advance(30.0);
  EXPECT_TRUE(lake.isLakeOf(parameters, 0.2, -0.1));
  EXPECT_FALSE(lake.isLakeOf(parameters, 0.2, 0.0));
  for (int change = 0; change < 5; ++change) {
    DisturbanceParameters other = parameters;
    double* values[] = {&other.current_sigma, &other.current_time_constant, &other.navigation_sigma,
                        &other.navigation_time_constant};
    if (change < 4) {
      *values[change] += 0.5;
    } else {
      other.seed = 2;
    }
    EXPECT_FALSE(lake.isLakeOf(other, 0.2, -0.1)) << change;
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
