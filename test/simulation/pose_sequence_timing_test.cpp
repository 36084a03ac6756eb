#include "trajectory_generation_tools/simulation/pose_sequence_timing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace kinematic_coverage::core {
namespace {

TEST(PoseSequenceTiming, AStraightLineTakesTheTrapezoidalProfilesTime) {
  // 10 m from rest to rest at v_max 0.5 m/s and a_max 0.2 m/s^2: L / v + v / a.
  const VehicleLimits limits;
  std::vector<Pose2> line;
  for (int k = 0; k <= 100; ++k) line.push_back({0.1 * k, 0.0, 0.0});
  const std::vector<double> times = PoseSequenceTiming(limits).times(line);
  ASSERT_EQ(times.size(), line.size());
  EXPECT_NEAR(times.back(), 10.0 / limits.v_max + limits.v_max / limits.a_max, 1e-9);
  for (std::size_t k = 1; k < times.size(); ++k) EXPECT_GT(times[k], times[k - 1]);
}

TEST(PoseSequenceTiming, RotationsStopTheRobotAndTurnAtTheLargestYawRate) {
  // 5 m, a half turn in place, 5 m back: two trapezoids and pi / yaw_rate_max.
  const VehicleLimits limits;
  std::vector<Pose2> poses;
  for (int k = 0; k <= 50; ++k) poses.push_back({0.1 * k, 0.0, 0.0});
  poses.push_back({5.0, 0.0, M_PI / 2.0});
  poses.push_back({5.0, 0.0, M_PI});
  for (int k = 49; k >= 0; --k) poses.push_back({0.1 * k, 0.0, M_PI});
  const std::vector<double> times = PoseSequenceTiming(limits).times(poses);
  const double leg = 5.0 / limits.v_max + limits.v_max / limits.a_max;
  EXPECT_NEAR(times.back(), 2.0 * leg + M_PI / limits.yaw_rate_max, 1e-9);
}

TEST(PoseSequenceTiming, AnArcIsDrivenNoFasterThanItsYawRateAllows) {
  // A quarter circle of radius 0.4 m sampled densely: at most yaw_rate_max * r, here below
  // v_max, so its middle takes its length over that speed.
  const VehicleLimits limits;
  const double radius = 0.4;
  std::vector<Pose2> arc;
  for (int k = 0; k <= 200; ++k) {
    const double angle = M_PI / 2.0 * k / 200.0;
    arc.push_back({radius * std::sin(angle), radius * (1.0 - std::cos(angle)), angle});
  }
  const std::vector<double> times = PoseSequenceTiming(limits).times(arc);
  const double speed = limits.yaw_rate_max * radius;
  const double middle = times[150] - times[50];
  EXPECT_NEAR(middle, (M_PI / 2.0 * radius) / 2.0 / speed, 1e-3 * middle);
}

TEST(PoseSequenceTiming, FewerThanTwoPosesTakeNoTime) {
  const PoseSequenceTiming timing{VehicleLimits{}};
  EXPECT_TRUE(timing.times({}).empty());
  EXPECT_EQ(timing.times({{1.0, 2.0, 0.0}}), std::vector<double>{0.0});
}

}  // namespace
}  // namespace kinematic_coverage::core
