#include "coverage_system/tool/waypoint_csv_writer.h"

#include <cmath>
#include <stdexcept>

#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/base/text_file_writer.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {

std::string WaypointCsvWriter::format(const std::vector<Pose2>& waypoints) const {
  std::string text = "x,y,yaw\n";
  for (std::size_t i = 0; i < waypoints.size(); ++i) {
    const Pose2& pose = waypoints[i];
    if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.yaw)) {
      throw std::domain_error("waypoint " + std::to_string(i) + " is not finite");
    }
    text += formatRoundTrip(pose.x) + "," + formatRoundTrip(pose.y) + "," +
            formatRoundTrip(wrapAngle(pose.yaw)) + "\n";
  }
  return text;
}

void WaypointCsvWriter::write(const std::string& path, const std::vector<Pose2>& waypoints) const {
  writeTextFile(path, format(waypoints));
}

}  // namespace kinematic_coverage::core
