#pragma once

#include <string>
#include <vector>

#include "trajectory_generation_tools/trajectory/trajectory_pose.h"

namespace kinematic_coverage::core {

/// Writes `trajectory.csv` (docs/REFERENCE.md, File formats): a header row `t,x,y,yaw,kind`,
/// then one row per pose, yaw wrapped into (-pi, pi], kind `segment`, `arc` or `rotation`,
/// numbers in shortest round-trip form.
class TrajectoryCsvWriter {
 public:
  /// The file's text. Throws std::domain_error for a non-finite value (a bug upstream).
  std::string format(const std::vector<TrajectoryPose>& poses) const;

  /// Writes format() to `path`; InvalidInputError when the file cannot be written.
  void write(const std::string& path, const std::vector<TrajectoryPose>& poses) const;

  /// The CSV word for a primitive kind: "segment", "arc" or "rotation".
  static const char* kindName(PrimitiveKind kind);
};

}  // namespace kinematic_coverage::core
