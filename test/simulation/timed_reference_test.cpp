#include "trajectory_generation_tools/simulation/timed_reference.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {
namespace {

TEST(TimedReference, AConstantSpeedLineIsTrackedAtItsSpeedBetweenItsRestingEnds) {
  // Poses 0.5 m apart every second along x: inside, the reference moves at 0.5 m/s with no
  // acceleration; it holds the first pose before the start and the last after the end.
  std::vector<Pose2> poses;
  std::vector<double> times;
  for (int k = 0; k <= 10; ++k) {
    poses.push_back({0.5 * k, 2.0, 0.0});
    times.push_back(static_cast<double>(k));
  }
  const TimedReference reference(poses, times);
  EXPECT_DOUBLE_EQ(reference.endTime(), 10.0);
  for (const double t : {2.0, 3.25, 7.9}) {
    const ReferenceState state = reference.at(t);
    EXPECT_NEAR(state.position.x(), 0.5 * t, 1e-12) << t;
    EXPECT_NEAR(state.position.y(), 2.0, 1e-12) << t;
    EXPECT_NEAR(state.velocity.x(), 0.5, 1e-12) << t;
    EXPECT_NEAR(state.acceleration.norm(), 0.0, 1e-12) << t;
  }
  // The ends are at rest: the first piece accelerates from 0, the last brakes to 0.
  EXPECT_GT(reference.at(0.5).acceleration.x(), 0.0);
  EXPECT_LT(reference.at(9.5).acceleration.x(), 0.0);
  EXPECT_EQ(reference.at(-1.0).position, Point2(0.0, 2.0));
  EXPECT_EQ(reference.at(-1.0).velocity, Point2::Zero());
  EXPECT_EQ(reference.at(12.0).position, Point2(5.0, 2.0));
  EXPECT_EQ(reference.at(12.0).velocity, Point2::Zero());
}

TEST(TimedReference, ARotationInPlaceTurnsTheHeadingAtItsRateTheShortWay) {
  const TimedReference reference({{1.0, 1.0, 3.0}, {1.0, 1.0, -3.0}}, {0.0, 2.0});
  // From 3 rad to -3 rad the short way: counter-clockwise through pi, 2 pi - 6 rad in 2 s.
  const double turn = 2.0 * M_PI - 6.0;
  const ReferenceState half = reference.at(1.0);
  EXPECT_NEAR(reference.at(0.5).yaw, 3.0 + turn / 4.0, 1e-12);
  EXPECT_NEAR(reference.at(1.5).yaw, -3.0 - turn / 4.0, 1e-12);
  EXPECT_NEAR(half.yaw_rate, turn / 2.0, 1e-12);
  EXPECT_EQ(half.position, Point2(1.0, 1.0));
  EXPECT_EQ(half.velocity, Point2::Zero());
}

TEST(TimedReference, RejectsTimesThatDecreaseOrDoNotMatchThePoses) {
  EXPECT_THROW(TimedReference({}, {}), InvalidInputError);
  EXPECT_THROW(TimedReference({{0, 0, 0}, {1, 0, 0}}, {0.0}), InvalidInputError);
  EXPECT_THROW(TimedReference({{0, 0, 0}, {1, 0, 0}}, {1.0, 0.5}), InvalidInputError);
  EXPECT_THROW(TimedReference({{0, 0, 0}, {1, NAN, 0}}, {0.0, 1.0}), InvalidInputError);
}

}  // namespace
}  // namespace kinematic_coverage::core
