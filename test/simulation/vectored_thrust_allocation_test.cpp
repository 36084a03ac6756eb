#include "trajectory_generation_tools/simulation/vectored_thrust_allocation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace kinematic_coverage::core {
namespace {

constexpr double kThrustMax = 113.0;
constexpr double kTorqueMax = 30.0;

double largestShare(const std::array<double, 4>& shares) {
  double largest = 0.0;
  for (const double share : shares) largest = std::max(largest, std::abs(share));
  return largest;
}

TEST(VectoredThrustAllocation, EachAxisAloneReachesItsLimitWithEveryThrusterAtItsOwn) {
  const VectoredThrustAllocation allocation(kThrustMax, kTorqueMax);
  for (const BodyForces& demand :
       {BodyForces{kThrustMax, 0.0, 0.0}, BodyForces{0.0, kThrustMax, 0.0},
        BodyForces{0.0, 0.0, -kTorqueMax}}) {
    const std::array<double, 4> shares = allocation.thrusterShares(demand);
    for (const double share : shares) EXPECT_NEAR(std::abs(share), 1.0, 1e-12);
    const BodyForces achieved = allocation.achievable(demand);
    EXPECT_DOUBLE_EQ(achieved.surge, demand.surge);
    EXPECT_DOUBLE_EQ(achieved.sway, demand.sway);
    EXPECT_DOUBLE_EQ(achieved.yaw_torque, demand.yaw_torque);
  }
}

TEST(VectoredThrustAllocation, TheSharesGiveTheDemandAndAnUnmetDemandIsScaledWhole) {
  // On seeded random demands up to each axis's limit: the thrusters' shares give back
  // the demand (the configuration inverted); a demand within the limits is met as asked,
  // one beyond them is scaled down whole until the largest share is exactly one.
  const VectoredThrustAllocation allocation(kThrustMax, kTorqueMax);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> share(-1.0, 1.0);
  int met = 0;
  int scaled = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const BodyForces demand{share(rng) * kThrustMax, share(rng) * kThrustMax,
                            share(rng) * kTorqueMax};
    const BodyForces back = allocation.forcesOf(allocation.thrusterShares(demand));
    EXPECT_NEAR(back.surge, demand.surge, 1e-9);
    EXPECT_NEAR(back.sway, demand.sway, 1e-9);
    EXPECT_NEAR(back.yaw_torque, demand.yaw_torque, 1e-9);
    const BodyForces achieved = allocation.achievable(demand);
    const double largest = largestShare(allocation.thrusterShares(achieved));
    EXPECT_LE(largest, 1.0 + 1e-12);
    if (largestShare(allocation.thrusterShares(demand)) <= 1.0) {
      ++met;
      EXPECT_EQ(achieved.surge, demand.surge);
      EXPECT_EQ(achieved.sway, demand.sway);
      EXPECT_EQ(achieved.yaw_torque, demand.yaw_torque);
    } else {
      ++scaled;
      EXPECT_NEAR(largest, 1.0, 1e-12);
      const double scale = achieved.surge / demand.surge;
      EXPECT_GT(scale, 0.0);
      EXPECT_LT(scale, 1.0);
      EXPECT_NEAR(achieved.sway, scale * demand.sway, 1e-9);
      EXPECT_NEAR(achieved.yaw_torque, scale * demand.yaw_torque, 1e-9);
    }
  }
  EXPECT_GT(met, 100);
  EXPECT_GT(scaled, 100);
}

TEST(VectoredThrustAllocation, SurgeAndYawShareTheThrusters) {
  // The thrusters are shared: full surge and full yaw torque together are scaled to half
  // of each.
  const VectoredThrustAllocation allocation(kThrustMax, kTorqueMax);
  const BodyForces both = allocation.achievable({kThrustMax, 0.0, kTorqueMax});
  EXPECT_NEAR(both.surge, 0.5 * kThrustMax, 1e-9);
  EXPECT_NEAR(both.yaw_torque, 0.5 * kTorqueMax, 1e-9);
}

}  // namespace
}  // namespace kinematic_coverage::core
