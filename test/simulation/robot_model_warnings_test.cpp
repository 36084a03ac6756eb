#include "trajectory_generation_tools/simulation/robot_model_warnings.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace kinematic_coverage::core {
namespace {

TEST(RobotModelWarningsTest, NoneForTheDefaultsOrAToleranceAboveTheNavigationError) {
  RobotModel model;
  EXPECT_TRUE(robotModelWarnings(model).empty());
  model.disturbance.navigation_sigma = 0.1;
  model.position_tolerance = 0.3;
  EXPECT_TRUE(robotModelWarnings(model).empty());
}

TEST(RobotModelWarningsTest, AToleranceWithinTheNavigationErrorMakesItHunt) {
  // The setpoint follower hunts near every pose; the timed controller only where a run ends.
  RobotModel model;
  model.disturbance.navigation_sigma = 0.1;
  model.position_tolerance = 0.05;
  model.controller = TrackingController::kSetpoint;
  std::vector<std::string> warnings = robotModelWarnings(model);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0],
            "position_tolerance = 0.05 m is less than 3 x navigation_sigma = 0.3 m: the robot's "
            "estimate wanders beyond the tolerance, so it slows and hunts near every pose it is "
            "handed");
  model.controller = TrackingController::kTimed;
  warnings = robotModelWarnings(model);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0],
            "position_tolerance = 0.05 m is less than 3 x navigation_sigma = 0.3 m: the robot's "
            "estimate wanders beyond the tolerance, so it hunts at the last pose before it counts "
            "as arrived");
}

}  // namespace
}  // namespace kinematic_coverage::core
