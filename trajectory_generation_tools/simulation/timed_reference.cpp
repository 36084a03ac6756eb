#include "trajectory_generation_tools/simulation/timed_reference.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// s: pieces shorter than this hold their start (a rotation in place of no duration).
constexpr double kShortestPiece = 1e-9;

}  // namespace

TimedReference::TimedReference(std::vector<Pose2> poses, std::vector<double> times)
    : poses_(std::move(poses)), times_(std::move(times)) {
  if (poses_.empty() || poses_.size() != times_.size()) {
    throw InvalidInputError("a timed reference needs one time per pose, got " +
                            std::to_string(times_.size()) + " times for " +
                            std::to_string(poses_.size()) + " poses");
  }
  for (std::size_t k = 0; k < poses_.size(); ++k) {
    const Pose2& p = poses_[k];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.yaw) ||
        !std::isfinite(times_[k])) {
      throw InvalidInputError("pose " + std::to_string(k) +
                              " of the timed reference is not finite");
    }
    if (k > 0 && times_[k] < times_[k - 1]) {
      throw InvalidInputError("the trajectory's times decrease at pose " + std::to_string(k) +
                              " (" + std::to_string(times_[k]) + " s after " +
                              std::to_string(times_[k - 1]) + " s)");
    }
  }
  // Central differences; the ends at rest.
  velocities_.assign(poses_.size(), Point2::Zero());
  for (std::size_t k = 1; k + 1 < poses_.size(); ++k) {
    const double span = times_[k + 1] - times_[k - 1];
    if (span > kShortestPiece) {
      velocities_[k] = (poses_[k + 1].position() - poses_[k - 1].position()) / span;
    }
  }
}

std::size_t TimedReference::pieceAt(double t) const {
  const auto after = std::upper_bound(times_.begin(), times_.end(), t);
  if (after == times_.begin()) return 0;
  return std::min<std::size_t>(static_cast<std::size_t>(after - times_.begin()) - 1,
                               times_.size() - 1);
}

ReferenceState TimedReference::at(double t) const {
  ReferenceState state;
  const std::size_t k = pieceAt(t);
  if (t <= times_.front() || k + 1 >= poses_.size()) {
    const Pose2& held = t <= times_.front() ? poses_.front() : poses_.back();
    state.position = held.position();
    state.yaw = held.yaw;
    return state;
  }
  const double duration = times_[k + 1] - times_[k];
  if (duration <= kShortestPiece) {
    state.position = poses_[k + 1].position();
    state.yaw = poses_[k + 1].yaw;
    return state;
  }
  const double s = (t - times_[k]) / duration;
  const Pose2& from = poses_[k];
  const Pose2& to = poses_[k + 1];
  state.position = from.position() + s * (to.position() - from.position());
  const double turn = wrapAngle(to.yaw - from.yaw);
  state.yaw = wrapAngle(from.yaw + s * turn);
  state.yaw_rate = turn / duration;
  state.velocity = velocities_[k] + s * (velocities_[k + 1] - velocities_[k]);
  state.acceleration = (velocities_[k + 1] - velocities_[k]) / duration;
  return state;
}

}  // namespace kinematic_coverage::core
