#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "trajectory_generation_tools/path/path_primitive.h"
#include "trajectory_generation_tools/trajectory/trajectory_pose.h"

namespace kinematic_coverage::core {
namespace testing {

/// A random G1-continuous chain of `count` segments and arcs (alternating, random
/// lengths, radii and signed sweeps) from the origin heading along +x, as the smoothing
/// produces.
inline std::vector<PathPrimitive> randomG1Path(std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> length(0.05, 8.0);
  std::uniform_real_distribution<double> radius(0.2, 5.0);
  std::uniform_real_distribution<double> sweep(0.01, 3.0);
  std::bernoulli_distribution left(0.5);
  std::vector<PathPrimitive> path;
  Point2 at(0.0, 0.0);
  double heading = 0.0;
  for (int i = 0; i < count; ++i) {
    if (i % 2 == 0) {
      const Point2 to = at + length(rng) * Point2(std::cos(heading), std::sin(heading));
      path.push_back(PathPrimitive::segment(at, to));
      at = to;
    } else {
      const double r = radius(rng);
      const double side = left(rng) ? 1.0 : -1.0;
      const Point2 centre = at + side * r * Point2(-std::sin(heading), std::cos(heading));
      const double start_angle = std::atan2(at.y() - centre.y(), at.x() - centre.x());
      PathPrimitive arc = PathPrimitive::arc(centre, r, start_angle, side * sweep(rng));
      heading = arc.endPose().yaw;
      at = arc.end();
      path.push_back(arc);
    }
  }
  return path;
}

/// Checks the sampling rules (docs/REFERENCE.md, File formats) on `poses` sampled from `path`:
/// gaps within the intervals, every non-degenerate primitive's start and end present, no
/// repeated pose except a rotation's, yaw in (-pi, pi] and along the direction of travel.
inline void expectSamplingContract(const std::vector<PathPrimitive>& path,
                                   const std::vector<TrajectoryPose>& poses,
                                   double segment_distance, double arc_distance,
                                   double rotation_angle) {
  constexpr double kSlack = 1e-12;
  constexpr double kHeadingTolerance = 1e-6;
  ASSERT_FALSE(poses.empty());
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const TrajectoryPose& pose = poses[i];
    ASSERT_TRUE(std::isfinite(pose.x) && std::isfinite(pose.y) && std::isfinite(pose.yaw));
    EXPECT_GT(pose.yaw, -M_PI);
    EXPECT_LE(pose.yaw, M_PI);
    if (i == 0) continue;
    const TrajectoryPose& previous = poses[i - 1];
    const Point2 step = pose.position() - previous.position();
    const double gap = step.norm();
    switch (pose.kind) {
      case PrimitiveKind::kSegment:
        ASSERT_GT(gap, 0.0) << "pose " << i;
        EXPECT_LE(gap, segment_distance * (1.0 + kSlack)) << "pose " << i;
        EXPECT_NEAR(wrapAngle(std::atan2(step.y(), step.x()) - pose.yaw), 0.0, kHeadingTolerance)
            << "pose " << i;
        EXPECT_NEAR(wrapAngle(pose.yaw - previous.yaw), 0.0, kHeadingTolerance) << "pose " << i;
        break;
      case PrimitiveKind::kArc: {
        ASSERT_GT(gap, 0.0) << "pose " << i;
        EXPECT_LE(gap, arc_distance * (1.0 + kSlack)) << "pose " << i;
        // The chord of a circular arc heads along the tangent halfway between its ends.
        const double middle = previous.yaw + wrapAngle(pose.yaw - previous.yaw) / 2.0;
        EXPECT_NEAR(wrapAngle(std::atan2(step.y(), step.x()) - middle), 0.0, kHeadingTolerance)
            << "pose " << i;
        const PathPrimitive& arc = path[pose.primitive];
        const Point2 radial = pose.position() - arc.centre();
        const double tangent =
            std::atan2(radial.y(), radial.x()) + (arc.sweep() >= 0.0 ? M_PI_2 : -M_PI_2);
        EXPECT_NEAR(wrapAngle(tangent - pose.yaw), 0.0, kHeadingTolerance) << "pose " << i;
        break;
      }
      case PrimitiveKind::kClothoid: {
        ASSERT_GT(gap, 0.0) << "pose " << i;
        // Chords of a curve are no longer than its length between their ends.
        EXPECT_LE(gap, arc_distance * (1.0 + kSlack)) << "pose " << i;
        const PathPrimitive& clothoid = path[pose.primitive];
        const Pose2 exact = clothoid.poseAt(pose.fraction);
        EXPECT_LT((exact.position() - pose.position()).norm(), 1e-12) << "pose " << i;
        EXPECT_NEAR(wrapAngle(exact.yaw - pose.yaw), 0.0, kHeadingTolerance) << "pose " << i;
        break;
      }
      case PrimitiveKind::kRotation:
        EXPECT_EQ(gap, 0.0) << "pose " << i;
        EXPECT_GT(std::abs(wrapAngle(pose.yaw - previous.yaw)), 0.0) << "pose " << i;
        EXPECT_LE(std::abs(wrapAngle(pose.yaw - previous.yaw)), rotation_angle * (1.0 + kSlack))
            << "pose " << i;
        break;
    }
  }
  // Every primitive's start and end is a pose, in order.
  std::size_t cursor = 0;
  for (std::size_t p = 0; p < path.size(); ++p) {
    const PathPrimitive& primitive = path[p];
    if (primitive.kind() == PrimitiveKind::kRotation ? primitive.turnAngle() == 0.0
                                                     : primitive.length() <= 1e-6) {
      continue;
    }
    for (const Pose2& end : {primitive.startPose(), primitive.endPose()}) {
      while (cursor < poses.size() &&
             !((poses[cursor].position() - end.position()).norm() <= 1e-9 &&
               std::abs(wrapAngle(poses[cursor].yaw - end.yaw)) <= 1e-9)) {
        ++cursor;
      }
      ASSERT_LT(cursor, poses.size()) << "primitive " << p << " end missing";
    }
  }
}

}  // namespace testing
}  // namespace kinematic_coverage::core
