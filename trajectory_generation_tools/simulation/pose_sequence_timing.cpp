#include "trajectory_generation_tools/simulation/pose_sequence_timing.h"

#include <algorithm>
#include <cmath>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// m: poses closer than this share a position (an in-place rotation between them).
constexpr double kSamePosition = 1e-9;

}  // namespace

PoseSequenceTiming::PoseSequenceTiming(const VehicleLimits& limits) : limits_(limits) {}

double PoseSequenceTiming::pieceTime(double length, double entry, double exit, double cap) const {
  const double a = limits_.a_max;
  const double peak =
      std::min(cap, std::sqrt((2.0 * a * length + entry * entry + exit * exit) / 2.0));
  if (peak <= 0.0) return 0.0;
  const double speeding_up = (peak * peak - entry * entry) / (2.0 * a);
  const double braking = (peak * peak - exit * exit) / (2.0 * a);
  const double cruise = std::max(0.0, length - speeding_up - braking);
  return (peak - entry) / a + (peak - exit) / a + cruise / peak;
}

std::vector<double> PoseSequenceTiming::times(const std::vector<Pose2>& poses) const {
  const std::size_t n = poses.size();
  std::vector<double> times(n, 0.0);
  if (n < 2) return times;
  // Per piece k (pose k to k + 1): its length, whether it rotates in place, its speed cap.
  std::vector<double> length(n - 1), cap(n - 1);
  std::vector<bool> rotation(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    length[k] = (poses[k + 1].position() - poses[k].position()).norm();
    rotation[k] = length[k] <= kSamePosition;
    const double turn = std::abs(wrapAngle(poses[k + 1].yaw - poses[k].yaw));
    cap[k] = turn > 0.0 ? std::min(limits_.v_max, limits_.yaw_rate_max * length[k] / turn)
                        : limits_.v_max;
  }
  // Speed at each pose: the lower cap of its pieces, 0 at the ends and beside rotations,
  // then what a_max allows forwards and backwards.
  std::vector<double> speed(n, 0.0);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    speed[i] = rotation[i - 1] || rotation[i] ? 0.0 : std::min(cap[i - 1], cap[i]);
  }
  for (std::size_t i = 1; i < n; ++i) {
    speed[i] = std::min(
        speed[i], std::sqrt(speed[i - 1] * speed[i - 1] + 2.0 * limits_.a_max * length[i - 1]));
  }
  for (std::size_t i = n - 1; i-- > 0;) {
    speed[i] = std::min(speed[i],
                        std::sqrt(speed[i + 1] * speed[i + 1] + 2.0 * limits_.a_max * length[i]));
  }
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double piece =
        rotation[k] ? std::abs(wrapAngle(poses[k + 1].yaw - poses[k].yaw)) / limits_.yaw_rate_max
                    : pieceTime(length[k], speed[k], speed[k + 1], cap[k]);
    times[k + 1] = times[k] + piece;
  }
  return times;
}

}  // namespace kinematic_coverage::core
