#include "coverage_system/tool/trajectory_csv_writer.h"

#include <cmath>
#include <stdexcept>

#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/base/text_file_writer.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {

const char* TrajectoryCsvWriter::kindName(PrimitiveKind kind) {
  switch (kind) {
    case PrimitiveKind::kSegment:
      return "segment";
    case PrimitiveKind::kArc:
      return "arc";
    case PrimitiveKind::kRotation:
      return "rotation";
    case PrimitiveKind::kClothoid:
      return "clothoid";
  }
  return "segment";
}

std::string TrajectoryCsvWriter::format(const std::vector<TrajectoryPose>& poses) const {
  std::string text = "t,x,y,yaw,kind\n";
  text.reserve(text.size() + poses.size() * 64);
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const TrajectoryPose& pose = poses[i];
    if (!std::isfinite(pose.t) || !std::isfinite(pose.x) || !std::isfinite(pose.y) ||
        !std::isfinite(pose.yaw)) {
      throw std::domain_error("trajectory pose " + std::to_string(i) + " is not finite");
    }
    text += formatRoundTrip(pose.t);
    text += ',';
    text += formatRoundTrip(pose.x);
    text += ',';
    text += formatRoundTrip(pose.y);
    text += ',';
    text += formatRoundTrip(wrapAngle(pose.yaw));
    text += ',';
    text += kindName(pose.kind);
    text += '\n';
  }
  return text;
}

void TrajectoryCsvWriter::write(const std::string& path,
                                const std::vector<TrajectoryPose>& poses) const {
  writeTextFile(path, format(poses));
}

}  // namespace kinematic_coverage::core
