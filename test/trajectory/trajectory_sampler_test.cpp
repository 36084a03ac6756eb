#include "trajectory_generation_tools/trajectory/trajectory_sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "test/trajectory/trajectory_test_paths.h"
#include "trajectory_generation_tools/trajectory/segment_path_builder.h"

namespace kinematic_coverage::core {
namespace {

using testing::expectSamplingContract;

TEST(TrajectorySampler, CutsASegmentIntoEqualPiecesWithExactEnds) {
  const TrajectorySampler sampler(0.5, 0.1, 0.2);
  const std::vector<PathPrimitive> path = {PathPrimitive::segment({0, 0}, {1.2, 0})};
  const std::vector<TrajectoryPose> poses = sampler.sample(path);
  ASSERT_EQ(poses.size(), 4u);  // ceil(1.2 / 0.5) = 3 pieces of 0.4 m
  for (std::size_t i = 0; i < poses.size(); ++i) {
    EXPECT_NEAR(poses[i].x, 0.4 * i, 1e-15);
    EXPECT_EQ(poses[i].y, 0.0);
    EXPECT_EQ(poses[i].yaw, 0.0);
    EXPECT_EQ(poses[i].kind, PrimitiveKind::kSegment);
  }
  EXPECT_EQ(poses.back().x, 1.2);
  EXPECT_EQ(poses.back().fraction, 1.0);
}

TEST(TrajectorySampler, ExactMultipleNeedsNoExtraPose) {
  const TrajectorySampler sampler(0.5, 0.1, 0.2);
  EXPECT_EQ(sampler.sample({PathPrimitive::segment({0, 0}, {0, 100})}).size(), 201u);
}

TEST(TrajectorySampler, ArcUsesArcIntervalAndTangentHeading) {
  const TrajectorySampler sampler(0.5, 0.1, 0.2);
  const std::vector<PathPrimitive> path = {
      PathPrimitive::segment({0, -1}, {1, -1}),
      PathPrimitive::arc({1, 0}, 1.0, -M_PI_2, M_PI),  // half circle, length pi
      PathPrimitive::segment({1, 1}, {0, 1})};
  const std::vector<TrajectoryPose> poses = sampler.sample(path);
  // 2 segment pieces + 32 arc pieces + 2 segment pieces, shared joints once.
  EXPECT_EQ(poses.size(), 1u + 2u + 32u + 2u);
  expectSamplingContract(path, poses, 0.5, 0.1, 0.2);
  EXPECT_NEAR(std::abs(poses.back().yaw), M_PI, 1e-12);
}

TEST(TrajectorySampler, ClothoidUsesArcIntervalAndItsExactPoses) {
  const TrajectorySampler sampler(0.5, 0.1, 0.2);
  const PathPrimitive clothoid = PathPrimitive::clothoid({1, 0, 0}, 0.0, 2.0, 1.05);
  const std::vector<PathPrimitive> path = {
      PathPrimitive::segment({0, 0}, {1, 0}), clothoid,
      PathPrimitive::segment(clothoid.end(),
                             clothoid.end() + Point2(std::cos(clothoid.endPose().yaw),
                                                     std::sin(clothoid.endPose().yaw)))};
  const std::vector<TrajectoryPose> poses = sampler.sample(path);
  // 2 + 11 + 2 pieces, shared joints once.
  EXPECT_EQ(poses.size(), 1u + 2u + 11u + 2u);
  EXPECT_EQ(poses[5].kind, PrimitiveKind::kClothoid);
  expectSamplingContract(path, poses, 0.5, 0.1, 0.2);
}

TEST(TrajectorySampler, RotationPosesShareAPositionAndStepByTheAngle) {
  const TrajectorySampler sampler(0.5, 0.1, 0.2);
  const std::vector<PathPrimitive> path =
      SegmentPathBuilder().build(std::vector<Point2>{{0, 0}, {1, 0}, {1, 1}});
  ASSERT_EQ(path.size(), 3u);
  const std::vector<TrajectoryPose> poses = sampler.sample(path);
  expectSamplingContract(path, poses, 0.5, 0.1, 0.2);
  std::size_t rotation_poses = 0;
  for (const TrajectoryPose& pose : poses) {
    if (pose.kind != PrimitiveKind::kRotation) continue;
    ++rotation_poses;
    EXPECT_EQ(pose.x, 1.0);
    EXPECT_EQ(pose.y, 0.0);
  }
  EXPECT_EQ(rotation_poses, 8u);  // ceil((pi/2) / 0.2) = 8 steps after the shared start
  EXPECT_EQ(poses.size(), 3u + 8u + 2u);
}

TEST(TrajectorySampler, RandomG1PathsKeepTheContract) {
  std::mt19937 rng(4242);
  std::uniform_real_distribution<double> interval(0.05, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    const std::vector<PathPrimitive> path = testing::randomG1Path(rng, 1 + trial % 15);
    const double segment_distance = interval(rng);
    const double arc_distance = interval(rng) / 5.0;
    const TrajectorySampler sampler(segment_distance, arc_distance, 0.2);
    const std::vector<TrajectoryPose> poses = sampler.sample(path);
    SCOPED_TRACE(trial);
    expectSamplingContract(path, poses, segment_distance, arc_distance, 0.2);
    for (std::size_t i = 1; i < poses.size(); ++i) {
      EXPECT_NE(poses[i].kind, PrimitiveKind::kRotation);
    }
  }
}

TEST(TrajectorySampler, RandomSegmentPathsWithRotationsKeepTheContract) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-20.0, 20.0);
  std::uniform_real_distribution<double> angle(0.01, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<Point2> waypoints;
    for (int i = 0; i < 2 + trial % 12; ++i) {
      waypoints.emplace_back(coordinate(rng), coordinate(rng));
      if (trial % 3 == 0) waypoints.push_back(waypoints.back());  // duplicates
    }
    const std::vector<PathPrimitive> path = SegmentPathBuilder().build(waypoints);
    const double rotation_angle = angle(rng);
    const std::vector<TrajectoryPose> poses =
        TrajectorySampler(0.5, 0.1, rotation_angle).sample(path);
    SCOPED_TRACE(trial);
    expectSamplingContract(path, poses, 0.5, 0.1, rotation_angle);
  }
}

TEST(TrajectorySampler, YawWrapsOnAnArcThroughPi) {
  // Counter-clockwise over the upper left of the origin: the heading passes through pi.
  const PathPrimitive arc = PathPrimitive::arc({0, 0}, 1.0, M_PI / 4, M_PI / 2);
  const std::vector<TrajectoryPose> poses = TrajectorySampler(0.5, 0.05, 0.2).sample({arc});
  bool positive = false;
  bool negative = false;
  for (const TrajectoryPose& pose : poses) {
    EXPECT_GT(pose.yaw, -M_PI);
    EXPECT_LE(pose.yaw, M_PI);
    positive = positive || pose.yaw > 3.0;
    negative = negative || pose.yaw < -3.0;
  }
  EXPECT_TRUE(positive && negative);
  expectSamplingContract({arc}, poses, 0.5, 0.05, 0.2);
}

TEST(TrajectorySampler, SkipsZeroLengthPrimitives) {
  const std::vector<PathPrimitive> path = {
      PathPrimitive::segment({0, 0}, {0, 0}), PathPrimitive::segment({0, 0}, {1, 0}),
      PathPrimitive::segment({1, 0}, {1, 0}), PathPrimitive::rotation({1, 0}, 0.0, 0.0),
      PathPrimitive::segment({1, 0}, {2, 0}), PathPrimitive::arc({2, 1}, 1.0, -M_PI_2, 0.0)};
  const std::vector<TrajectoryPose> poses = TrajectorySampler(0.5, 0.1, 0.2).sample(path);
  ASSERT_EQ(poses.size(), 5u);
  expectSamplingContract(path, poses, 0.5, 0.1, 0.2);
  for (const TrajectoryPose& pose : poses) EXPECT_EQ(pose.yaw, 0.0);
}

TEST(TrajectorySampler, OnlyDegeneratePrimitivesGiveOnePose) {
  const std::vector<TrajectoryPose> poses =
      TrajectorySampler(0.5, 0.1, 0.2).sample({PathPrimitive::rotation({3, 4}, 1.0, 0.0)});
  ASSERT_EQ(poses.size(), 1u);
  EXPECT_EQ(poses[0].x, 3.0);
  EXPECT_EQ(poses[0].y, 4.0);
  EXPECT_EQ(poses[0].yaw, 1.0);
  EXPECT_TRUE(TrajectorySampler(0.5, 0.1, 0.2).sample({}).empty());
}

TEST(TrajectorySampler, HeadingJumpWithoutRotationKeepsBothPoses) {
  const std::vector<PathPrimitive> path = {PathPrimitive::segment({0, 0}, {1, 0}),
                                           PathPrimitive::segment({1, 0}, {1, 1})};
  const std::vector<TrajectoryPose> poses = TrajectorySampler(0.5, 0.1, 0.2).sample(path);
  ASSERT_EQ(poses.size(), 6u);
  EXPECT_EQ(poses[2].position(), poses[3].position());
  EXPECT_EQ(poses[2].yaw, 0.0);
  EXPECT_NEAR(poses[3].yaw, M_PI_2, 1e-15);
}

TEST(TrajectorySampler, RejectsBadIntervalsAndBrokenPaths) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(TrajectorySampler(0.0, 0.1, 0.2), InvalidInputError);
  EXPECT_THROW(TrajectorySampler(0.5, -0.1, 0.2), InvalidInputError);
  EXPECT_THROW(TrajectorySampler(0.5, 0.1, nan), InvalidInputError);
  EXPECT_THROW(TrajectorySampler(inf, 0.1, 0.2), InvalidInputError);
  const TrajectorySampler sampler(0.5, 0.1, 0.2);
  EXPECT_THROW(sampler.sample({PathPrimitive::segment({0, 0}, {1, 0}),
                               PathPrimitive::segment({1, 0.1}, {2, 0})}),
               InvalidInputError);
  EXPECT_THROW(sampler.sample({PathPrimitive::segment({0, 0}, {nan, 0})}), InvalidInputError);
  EXPECT_THROW(sampler.sample({PathPrimitive::arc({0, 0}, -1.0, 0.0, 1.0)}), InvalidInputError);
  EXPECT_THROW(sampler.sample({PathPrimitive::arc({0, 0}, 1.0, 0.0, inf)}), InvalidInputError);
  EXPECT_THROW(TrajectorySampler(1e-9, 0.1, 0.2).sample({PathPrimitive::segment({0, 0}, {1e3, 0})}),
               InvalidInputError);
}

}  // namespace
}  // namespace kinematic_coverage::core
