#include "trajectory_generation_tools/trajectory/trajectory_timing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "test/trajectory/trajectory_test_paths.h"
#include "trajectory_generation_tools/trajectory/segment_path_builder.h"
#include "trajectory_generation_tools/trajectory/trajectory_sampler.h"

namespace kinematic_coverage::core {
namespace {

/// The planner's rest-to-rest trapezoidal time of a straight segment (segment_cost.h).
double trapezoidTime(double length, double v, double a) {
  return length >= v * v / a ? length / v + v / a : 2.0 * std::sqrt(length / a);
}

/// Stopping at every joint: the rest-to-rest trapezoid time of each segment (each arc at
/// its own limit) plus every rotation at yaw_rate, an upper bound of the model's time.
double stopAtEveryJointTime(const std::vector<PathPrimitive>& path, double v, double a,
                            double yaw_rate) {
  double time = 0.0;
  for (const PathPrimitive& primitive : path) {
    switch (primitive.kind()) {
      case PrimitiveKind::kRotation:
        time += primitive.turnAngle() / yaw_rate;
        break;
      case PrimitiveKind::kSegment:
        time += trapezoidTime(primitive.length(), v, a);
        break;
      case PrimitiveKind::kArc:
        time += trapezoidTime(primitive.length(), std::min(v, yaw_rate * primitive.radius()), a);
        break;
    }
  }
  return time;
}

/// t non-decreasing, strictly increasing between different positions, and no average
/// speed between consecutive poses above the limit of the primitive driven.
void expectTimesConsistent(const std::vector<PathPrimitive>& path,
                           const std::vector<TrajectoryPose>& poses, double v_max,
                           double yaw_rate_max) {
  ASSERT_FALSE(poses.empty());
  EXPECT_EQ(poses.front().t, 0.0);
  for (std::size_t i = 1; i < poses.size(); ++i) {
    const double dt = poses[i].t - poses[i - 1].t;
    const double ds = (poses[i].position() - poses[i - 1].position()).norm();
    ASSERT_GE(dt, 0.0) << "pose " << i;
    if (ds > 0.0) {
      ASSERT_GT(dt, 0.0) << "pose " << i;
      double limit = v_max;
      if (poses[i].kind == PrimitiveKind::kArc) {
        limit = std::min(v_max, yaw_rate_max * path[poses[i].primitive].radius());
      }
      EXPECT_LE(ds / dt, limit * (1.0 + 1e-9)) << "pose " << i;
    }
    if (poses[i].kind == PrimitiveKind::kRotation) {
      EXPECT_NEAR(dt, std::abs(wrapAngle(poses[i].yaw - poses[i - 1].yaw)) / yaw_rate_max, 1e-9);
    }
  }
}

TEST(TrajectoryTiming, StraightSegmentTakesTheTrapezoidTime) {
  const double v = 0.5;
  const double a = 0.2;
  const TrajectoryTiming timing(v, a, 0.5);
  for (const double length : {1e-3, 0.1, 1.0, 1.25, 1.3, 5.0, 100.0, 12345.6}) {
    const std::vector<PathPrimitive> path = {PathPrimitive::segment({1, 2}, {1 + length, 2})};
    EXPECT_NEAR(timing.traversalTime(path), trapezoidTime(length, v, a),
                1e-12 * trapezoidTime(length, v, a))
        << length;
  }
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> positive(0.01, 10.0);
  for (int trial = 0; trial < 1000; ++trial) {
    const double length = positive(rng) * positive(rng);
    const double vel = positive(rng);
    const double acc = positive(rng);
    const TrajectoryTiming random_timing(vel, acc, 1.0);
    const double expected = trapezoidTime(length, vel, acc);
    EXPECT_NEAR(random_timing.traversalTime({PathPrimitive::segment({0, 0}, {0, length})}),
                expected, 1e-12 * expected);
  }
}

TEST(TrajectoryTiming, SampledTimesFollowTheTrapezoid) {
  // 10 m at v 0.5, a 0.2: accelerate over 0.625 m (2.5 s), cruise, brake over 0.625 m.
  const std::vector<PathPrimitive> path = {PathPrimitive::segment({0, 0}, {10, 0})};
  std::vector<TrajectoryPose> poses = TrajectorySampler(0.125, 0.1, 0.2).sample(path);
  const double total = TrajectoryTiming(0.5, 0.2, 0.5).assignTimes(path, poses);
  EXPECT_NEAR(total, 22.5, 1e-12);
  for (const TrajectoryPose& pose : poses) {
    double expected = 0.0;
    if (pose.x <= 0.625) {
      expected = std::sqrt(2.0 * pose.x / 0.2);
    } else if (pose.x <= 9.375) {
      expected = 2.5 + (pose.x - 0.625) / 0.5;
    } else {
      expected = 22.5 - std::sqrt(2.0 * (10.0 - pose.x) / 0.2);
    }
    EXPECT_NEAR(pose.t, expected, 1e-9) << pose.x;
  }
  expectTimesConsistent(path, poses, 0.5, 0.5);
}

TEST(TrajectoryTiming, G1SegmentArcSegmentDoesNotStop) {
  const double v = 0.5;
  const double a = 0.2;
  const double yaw_rate = 0.5;
  const double r = 0.5;  // arc limit yaw_rate * r = 0.25 m/s
  const std::vector<PathPrimitive> path = {PathPrimitive::segment({0, 0}, {5, 0}),
                                           PathPrimitive::arc({5, r}, r, -M_PI_2, M_PI_2),
                                           PathPrimitive::segment({5 + r, r}, {5 + r, r + 6})};
  const TrajectoryTiming timing(v, a, yaw_rate);
  const std::vector<PrimitiveTiming> profile = timing.profile(path);
  ASSERT_EQ(profile.size(), 3u);
  EXPECT_NEAR(profile[0].exit_speed, 0.25, 1e-15);
  EXPECT_NEAR(profile[1].entry_speed, 0.25, 1e-15);
  EXPECT_NEAR(profile[1].peak_speed, 0.25, 1e-15);
  EXPECT_NEAR(profile[1].speed_limit, 0.25, 1e-15);
  EXPECT_NEAR(profile[2].entry_speed, 0.25, 1e-15);
  // Segment 1: 0 -> 0.5 over 0.625 m, brake to 0.25 over 0.46875 m; arc at 0.25; segment 2:
  // 0.25 -> 0.5 over 0.46875 m, brake to rest over 0.625 m.
  const double first = 2.5 + (5.0 - 0.625 - 0.46875) / v + 1.25;
  const double arc = r * M_PI_2 / 0.25;
  const double second = 1.25 + (6.0 - 0.46875 - 0.625) / v + 2.5;
  EXPECT_NEAR(timing.traversalTime(path), first + arc + second, 1e-12);
  EXPECT_NEAR(profile[1].duration_s, arc, 1e-12);
  EXPECT_LT(timing.traversalTime(path),
            trapezoidTime(5, v, a) + trapezoidTime(6, v, a) + arc);  // faster than stopping

  std::vector<TrajectoryPose> poses = TrajectorySampler(0.5, 0.1, 0.2).sample(path);
  timing.assignTimes(path, poses);
  expectTimesConsistent(path, poses, v, yaw_rate);
}

TEST(TrajectoryTiming, ShortPrimitivesNeverReachTheirLimit) {
  // Two 0.1 m segments joined G1: one accelerate-brake triangle over 0.2 m.
  const std::vector<PathPrimitive> path = {PathPrimitive::segment({0, 0}, {0.1, 0}),
                                           PathPrimitive::segment({0.1, 0}, {0.2, 0})};
  const TrajectoryTiming timing(0.5, 0.2, 0.5);
  EXPECT_NEAR(timing.traversalTime(path), trapezoidTime(0.2, 0.5, 0.2), 1e-12);
  EXPECT_NEAR(timing.profile(path)[0].exit_speed, std::sqrt(2 * 0.2 * 0.1), 1e-15);
}

TEST(TrajectoryTiming, RotationIsStopRotateGo) {
  const double v = 0.5;
  const double a = 0.2;
  const double yaw_rate = 0.4;
  const std::vector<PathPrimitive> path =
      SegmentPathBuilder().build(std::vector<Point2>{{0, 0}, {3, 0}, {3, -2}, {0, -2}});
  ASSERT_EQ(path.size(), 5u);
  const TrajectoryTiming timing(v, a, yaw_rate);
  const double expected =
      trapezoidTime(3, v, a) + trapezoidTime(2, v, a) + trapezoidTime(3, v, a) + M_PI / yaw_rate;
  EXPECT_NEAR(timing.traversalTime(path), expected, 1e-12);
  const std::vector<PrimitiveTiming> profile = timing.profile(path);
  EXPECT_NEAR(profile[1].duration_s, M_PI_2 / yaw_rate, 1e-15);
  EXPECT_EQ(profile[0].exit_speed, 0.0);
  EXPECT_EQ(profile[2].entry_speed, 0.0);
}

TEST(TrajectoryTiming, HeadingJumpWithoutRotationStops) {
  const std::vector<PathPrimitive> path = {PathPrimitive::segment({0, 0}, {3, 0}),
                                           PathPrimitive::segment({3, 0}, {3, 4})};
  const TrajectoryTiming timing(0.5, 0.2, 0.5);
  EXPECT_NEAR(timing.traversalTime(path), trapezoidTime(3, 0.5, 0.2) + trapezoidTime(4, 0.5, 0.2),
              1e-12);
  std::vector<TrajectoryPose> poses = TrajectorySampler(0.5, 0.1, 0.2).sample(path);
  timing.assignTimes(path, poses);
  expectTimesConsistent(path, poses, 0.5, 0.5);
}

TEST(TrajectoryTiming, SegmentPathsMatchThePlannerCostPlusRotations) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> coordinate(-30.0, 30.0);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Point2> waypoints;
    for (int i = 0; i < 2 + trial % 20; ++i)
      waypoints.emplace_back(coordinate(rng), coordinate(rng));
    const std::vector<PathPrimitive> path = SegmentPathBuilder().build(waypoints);
    const TrajectoryTiming timing(0.5, 0.2, 0.5);
    const double expected = stopAtEveryJointTime(path, 0.5, 0.2, 0.5);
    std::vector<TrajectoryPose> poses = TrajectorySampler(0.5, 0.1, 0.2).sample(path);
    EXPECT_NEAR(timing.assignTimes(path, poses), expected, 1e-9 * expected);
    EXPECT_NEAR(poses.back().t, expected, 1e-9 * expected);
    expectTimesConsistent(path, poses, 0.5, 0.5);
  }
}

TEST(TrajectoryTiming, RandomG1PathsRespectTheVelocityModel) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> rate(0.1, 2.0);
  for (int trial = 0; trial < 300; ++trial) {
    const std::vector<PathPrimitive> path = testing::randomG1Path(rng, 1 + trial % 12);
    const double v = rate(rng);
    const double a = rate(rng);
    const double yaw_rate = rate(rng);
    const TrajectoryTiming timing(v, a, yaw_rate);
    const std::vector<PrimitiveTiming> profile = timing.profile(path);
    SCOPED_TRACE(trial);
    double length = 0.0;
    for (std::size_t i = 0; i < path.size(); ++i) {
      length += path[i].length();
      EXPECT_LE(profile[i].peak_speed, profile[i].speed_limit * (1 + 1e-12));
      EXPECT_LE(profile[i].entry_speed, profile[i].peak_speed);
      EXPECT_LE(profile[i].exit_speed, profile[i].peak_speed);
      // Speed changes no faster than a_max allows.
      const double change = std::abs(profile[i].exit_speed * profile[i].exit_speed -
                                     profile[i].entry_speed * profile[i].entry_speed);
      EXPECT_LE(change, 2 * a * path[i].length() * (1 + 1e-9) + 1e-12);
      if (i > 0) {
        EXPECT_EQ(profile[i].entry_speed, profile[i - 1].exit_speed);
        EXPECT_GT(profile[i].entry_speed, 0.0);  // G1 joints: no stop
        EXPECT_NEAR(profile[i].start_time_s,
                    profile[i - 1].start_time_s + profile[i - 1].duration_s, 1e-12);
      }
    }
    EXPECT_EQ(profile.front().entry_speed, 0.0);
    EXPECT_EQ(profile.back().exit_speed, 0.0);
    const double total = timing.traversalTime(path);
    EXPECT_GE(total, length / v * (1 - 1e-12));  // never faster than v_max throughout
    EXPECT_LE(total, stopAtEveryJointTime(path, v, a, yaw_rate) * (1 + 1e-12));
    std::vector<TrajectoryPose> poses = TrajectorySampler(0.3, 0.05, 0.2).sample(path);
    EXPECT_NEAR(timing.assignTimes(path, poses), total, 0.0);
    EXPECT_NEAR(poses.back().t, total, 1e-9 * total);
    expectTimesConsistent(path, poses, v, yaw_rate);
  }
}

TEST(TrajectoryTiming, DegenerateInput) {
  const TrajectoryTiming timing(0.5, 0.2, 0.5);
  EXPECT_EQ(timing.traversalTime({}), 0.0);
  std::vector<TrajectoryPose> none;
  EXPECT_EQ(timing.assignTimes({}, none), 0.0);
  // Single waypoint: one pose at t = 0.
  const std::vector<PathPrimitive> single =
      SegmentPathBuilder().build(std::vector<Pose2>{{1, 2, 0.3}});
  std::vector<TrajectoryPose> poses = TrajectorySampler(0.5, 0.1, 0.2).sample(single);
  EXPECT_EQ(timing.assignTimes(single, poses), 0.0);
  ASSERT_EQ(poses.size(), 1u);
  EXPECT_EQ(poses[0].t, 0.0);
  // Zero-length segments between collinear ones change nothing.
  const std::vector<PathPrimitive> with_points = {
      PathPrimitive::segment({0, 0}, {0, 0}), PathPrimitive::segment({0, 0}, {2, 0}),
      PathPrimitive::segment({2, 0}, {2, 0}), PathPrimitive::segment({2, 0}, {5, 0})};
  EXPECT_NEAR(timing.traversalTime(with_points), trapezoidTime(5, 0.5, 0.2), 1e-12);
  // A full reversal: two legs and a pi rotation.
  const std::vector<PathPrimitive> reversal =
      SegmentPathBuilder().build(std::vector<Point2>{{0, 0}, {4, 0}, {1, 0}});
  EXPECT_NEAR(timing.traversalTime(reversal),
              trapezoidTime(4, 0.5, 0.2) + trapezoidTime(3, 0.5, 0.2) + M_PI / 0.5, 1e-12);
  // A pose naming a primitive the path does not have.
  std::vector<TrajectoryPose> stray(1);
  stray[0].primitive = 3;
  EXPECT_THROW(timing.assignTimes(reversal, stray), InvalidInputError);
}

TEST(TrajectoryTiming, RejectsBadRates) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(TrajectoryTiming(0.0, 0.2, 0.5), InvalidInputError);
  EXPECT_THROW(TrajectoryTiming(0.5, -1.0, 0.5), InvalidInputError);
  EXPECT_THROW(TrajectoryTiming(0.5, 0.2, nan), InvalidInputError);
  EXPECT_THROW(TrajectoryTiming(std::numeric_limits<double>::infinity(), 0.2, 0.5),
               InvalidInputError);
  EXPECT_NO_THROW(TrajectoryTiming{VehicleLimits()});
}

}  // namespace
}  // namespace kinematic_coverage::core
