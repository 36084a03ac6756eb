#include "polygon_coverage_ros_bridge/sweeps/waypoint_path_poses.h"

#include <cmath>
#include <sstream>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// Appends the poses of an in-place rotation at `position` from `from` to `to` (the
/// shorter way), excluding the start and including the end.
void appendRotation(const Point2& position, double from, double to, double rotation_step,
                    std::vector<Pose2>& poses) {
  const double turn = wrapAngle(to - from);
  const int samples = static_cast<int>(std::ceil(std::abs(turn) / rotation_step));
  for (int k = 1; k <= samples; ++k) {
    poses.push_back({position.x(), position.y(), wrapAngle(from + turn * k / samples)});
  }
}

}  // namespace

std::vector<Pose2> waypointPathPoses(const std::vector<Pose2>& waypoints, double rotation_step) {
  if (!(rotation_step > 0.0) || !std::isfinite(rotation_step)) {
    std::ostringstream message;
    message << "coverage: rotation step " << rotation_step << " must be finite and > 0";
    throw InvalidInputError(message.str());
  }
  for (std::size_t i = 0; i < waypoints.size(); ++i) {
    const Pose2& w = waypoints[i];
    if (!std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.yaw)) {
      std::ostringstream message;
      message << "coverage: waypoint " << i << " has a non-finite coordinate or heading";
      throw InvalidInputError(message.str());
    }
  }
  std::vector<Point2> positions;
  for (const Pose2& w : waypoints) {
    if (positions.empty() || (w.position() - positions.back()).norm() > kSamePositionTolerance) {
      positions.push_back(w.position());
    }
  }
  std::vector<Pose2> poses;
  if (positions.empty()) return poses;
  if (positions.size() == 1) {
    poses.push_back({positions.front().x(), positions.front().y(), waypoints.front().yaw});
    return poses;
  }
  double heading = headingOf(positions[0], positions[1]);
  poses.push_back({positions[0].x(), positions[0].y(), heading});
  for (std::size_t i = 1; i < positions.size(); ++i) {
    poses.push_back({positions[i].x(), positions[i].y(), heading});
    if (i + 1 < positions.size()) {
      const double next_heading = headingOf(positions[i], positions[i + 1]);
      appendRotation(positions[i], heading, next_heading, rotation_step, poses);
      heading = next_heading;
    }
  }
  return poses;
}

}  // namespace kinematic_coverage::core
