#include "trajectory_generation_tools/trajectory/trajectory_thinning.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// A trajectory as the sampler makes it: 100 m east in 0.5 m steps (primitive 0), a
/// quarter turn in place (primitive 1), a 5 m quarter arc left in 0.05 rad steps
/// (primitive 2), then 60 m north (primitive 3).
std::vector<TrajectoryPose> sampledTrajectory() {
  std::vector<TrajectoryPose> poses;
  auto add = [&](double x, double y, double yaw, PrimitiveKind kind, std::uint32_t primitive) {
    TrajectoryPose pose;
    pose.t = static_cast<double>(poses.size());
    pose.x = x;
    pose.y = y;
    pose.yaw = yaw;
    pose.kind = kind;
    pose.primitive = primitive;
    poses.push_back(pose);
  };
  for (int i = 0; i <= 200; ++i) add(0.5 * i, 0.0, 0.0, PrimitiveKind::kSegment, 0);
  for (int i = 1; i <= 8; ++i) add(100.0, 0.0, -M_PI / 16 * i, PrimitiveKind::kRotation, 1);
  // Back to east, then the arc about (100, 5).
  for (int i = 1; i <= 8; ++i)
    add(100.0, 0.0, -M_PI / 2 + M_PI / 16 * i, PrimitiveKind::kRotation, 1);
  const int arc_steps = static_cast<int>(std::round((M_PI / 2) / 0.05));
  for (int i = 1; i <= arc_steps; ++i) {
    const double heading = M_PI / 2 * i / arc_steps;
    add(100.0 + 5.0 * std::sin(heading), 5.0 - 5.0 * std::cos(heading), heading,
        PrimitiveKind::kArc, 2);
  }
  for (int i = 1; i <= 120; ++i) add(105.0, 5.0 + 0.5 * i, M_PI / 2, PrimitiveKind::kSegment, 3);
  return poses;
}

TEST(TrajectoryThinning, ZeroSpacingKeepsEveryPose) {
  const std::vector<TrajectoryPose> poses = sampledTrajectory();
  EXPECT_EQ(TrajectoryThinning(0.0).apply(poses).size(), poses.size());
}

TEST(TrajectoryThinning, KeepsPrimitiveEndsRotationsAndCurvesAndOnePosePerSpacing) {
  const std::vector<TrajectoryPose> poses = sampledTrajectory();
  const std::vector<TrajectoryPose> kept = TrajectoryThinning(10.0).apply(poses);
  ASSERT_LT(kept.size(), poses.size() / 3);
  EXPECT_EQ(kept.front().t, poses.front().t);
  EXPECT_EQ(kept.back().t, poses.back().t);
  // Kept poses are poses of the trajectory, in order.
  std::size_t next = 0;
  for (const TrajectoryPose& pose : kept) {
    while (next < poses.size() && poses[next].t != pose.t) ++next;
    ASSERT_LT(next, poses.size()) << "pose at t " << pose.t << " is not one of the trajectory's";
  }
  // Every primitive's end and every rotation pose is kept.
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const bool end = i + 1 == poses.size() || poses[i + 1].primitive != poses[i].primitive;
    if (!end && poses[i].kind != PrimitiveKind::kRotation) continue;
    bool found = false;
    for (const TrajectoryPose& pose : kept) found = found || pose.t == poses[i].t;
    EXPECT_TRUE(found) << "pose " << i;
  }
  // Between kept poses: at most the spacing (plus one sample) of travel, and on the arc at
  // most kMaxHeadingStep (plus one sample's 0.05 rad) of turn.
  for (std::size_t k = 1; k < kept.size(); ++k) {
    const double gap = std::hypot(kept[k].x - kept[k - 1].x, kept[k].y - kept[k - 1].y);
    EXPECT_LE(gap, 10.0 + 0.5 + 1e-9) << k;
    if (kept[k].kind == PrimitiveKind::kArc) {
      EXPECT_LE(std::abs(wrapAngle(kept[k].yaw - kept[k - 1].yaw)),
                TrajectoryThinning::kMaxHeadingStep + 0.05 + 1e-9)
          << k;
    }
  }
}

TEST(TrajectoryThinning, RejectsANegativeOrNonFiniteSpacing) {
  EXPECT_THROW(TrajectoryThinning(-1.0), InvalidInputError);
  EXPECT_THROW(TrajectoryThinning(std::numeric_limits<double>::quiet_NaN()), InvalidInputError);
  EXPECT_THROW(TrajectoryThinning(std::numeric_limits<double>::infinity()), InvalidInputError);
}

}  // namespace
}  // namespace kinematic_coverage::core
