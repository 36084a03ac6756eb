#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// The reference of a timed trajectory at one instant, in the world frame.
struct ReferenceState {
  Point2 position;                       ///< p_d(t), m
  Point2 velocity = Point2::Zero();      ///< p_d'(t), m/s
  Point2 acceleration = Point2::Zero();  ///< p_d''(t), m/s^2
  double yaw = 0.0;                      ///< heading, rad in (-pi, pi]
  double yaw_rate = 0.0;                 ///< rad/s
};

/// A trajectory's poses with their times (the `t` column) as a reference p_d(t) that a
/// controller tracks (controller: timed): positions and headings interpolated linearly
/// between poses, the velocity interpolated between the poses' velocities (central
/// differences; zero at the ends, where the trajectory starts and ends at rest) so that the
/// reference's acceleration is finite and fed forward. Before the first time it holds the
/// first pose, after the last the last.
class TimedReference {
 public:
  /// Throws InvalidInputError for no poses, sizes that differ, a non-finite value, or times
  /// that decrease.
  TimedReference(std::vector<Pose2> poses, std::vector<double> times);

  ReferenceState at(double t) const;

  /// s: the last pose's time.
  double endTime() const { return times_.back(); }
  const Pose2& lastPose() const { return poses_.back(); }
  /// The index of the pose the reference is heading to at `t` (the end of its piece).
  std::size_t pieceEnd(double t) const { return std::min(pieceAt(t) + 1, poses_.size() - 1); }

 private:
  /// The index k of the piece [t_k, t_k+1] that holds `t` (times clamped to the ends).
  std::size_t pieceAt(double t) const;

  std::vector<Pose2> poses_;
  std::vector<double> times_;
  std::vector<Point2> velocities_;  ///< per pose
};

}  // namespace kinematic_coverage::core
