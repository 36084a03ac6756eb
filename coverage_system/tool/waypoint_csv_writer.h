#pragma once

#include <string>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// Writes `waypoints.csv` (docs/REFERENCE.md, File formats): a header row `x,y,yaw`, then
/// one row per waypoint, yaw wrapped into (-pi, pi], numbers in shortest round-trip form.
class WaypointCsvWriter {
 public:
  /// The file's text. Throws std::domain_error for a non-finite value (a bug upstream).
  std::string format(const std::vector<Pose2>& waypoints) const;

  /// Writes format() to `path`; InvalidInputError when the file cannot be written.
  void write(const std::string& path, const std::vector<Pose2>& waypoints) const;
};

}  // namespace kinematic_coverage::core
