#include "trajectory_generation_tools/simulation/pose_sequence_timing.h"

#include <algorithm>
#include <cmath>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {

PoseSequenceTiming::PoseSequenceTiming(const VehicleLimits& limits)
    : limits_(limits), profile_(limits) {}

std::vector<double> PoseSequenceTiming::times(const std::vector<Pose2>& poses) const {
  const std::size_t n = poses.size();
  std::vector<double> times(n, 0.0);
  if (n < 2) return times;
  // Per piece k (pose k to k + 1): its length, its turn, whether it rotates in place, its
  // speed cap.
  std::vector<double> length(n - 1), turn(n - 1), cap(n - 1);
  std::vector<bool> rotation(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    length[k] = (poses[k + 1].position() - poses[k].position()).norm();
    turn[k] = std::abs(wrapAngle(poses[k + 1].yaw - poses[k].yaw));
    rotation[k] = length[k] <= kSamePositionTolerance;
    cap[k] = turn[k] > 0.0 ? std::min(limits_.v_max, limits_.yaw_rate_max * length[k] / turn[k])
                           : limits_.v_max;
  }
  // Speed at each pose: the lower cap of its pieces, 0 at the ends and beside rotations,
  // then what a_max allows forwards and backwards.
  std::vector<double> speed(n, 0.0);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    speed[i] = rotation[i - 1] || rotation[i] ? 0.0 : std::min(cap[i - 1], cap[i]);
  }
  for (std::size_t i = 1; i < n; ++i) {
    speed[i] = std::min(speed[i], profile_.reachableSpeed(speed[i - 1], length[i - 1]));
  }
  for (std::size_t i = n - 1; i-- > 0;) {
    speed[i] = std::min(speed[i], profile_.reachableSpeed(speed[i + 1], length[i]));
  }
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double piece = rotation[k]
                             ? turn[k] / limits_.yaw_rate_max
                             : profile_.pieceTime(length[k], speed[k], speed[k + 1], cap[k]);
    times[k + 1] = times[k] + piece;
  }
  return times;
}

}  // namespace kinematic_coverage::core
