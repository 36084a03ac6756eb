#include "trajectory_generation_tools/trajectory/trajectory_thinning.h"

#include <cmath>
#include <string>

#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {

TrajectoryThinning::TrajectoryThinning(double spacing) : spacing_(spacing) {
  if (!(spacing >= 0.0) || !std::isfinite(spacing)) {
    throw InvalidInputError("trajectory thinning: the spacing " + formatNumber(spacing) +
                            " m is not a finite number >= 0");
  }
}

std::vector<TrajectoryPose> TrajectoryThinning::apply(
    const std::vector<TrajectoryPose>& poses) const {
  if (spacing_ == 0.0 || poses.size() <= 2) return poses;
  std::vector<TrajectoryPose> kept{poses.front()};
  double travelled = 0.0;
  for (std::size_t i = 1; i < poses.size(); ++i) {
    const TrajectoryPose& pose = poses[i];
    travelled += std::hypot(pose.x - poses[i - 1].x, pose.y - poses[i - 1].y);
    const bool primitive_end = i + 1 == poses.size() || poses[i + 1].primitive != pose.primitive;
    const bool turned = std::abs(wrapAngle(pose.yaw - kept.back().yaw)) >= kMaxHeadingStep;
    if (primitive_end || pose.kind == PrimitiveKind::kRotation || turned || travelled >= spacing_) {
      kept.push_back(pose);
      travelled = 0.0;
    }
  }
  return kept;
}

}  // namespace kinematic_coverage::core
