#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// One row of a trajectory or visited-poses file.
struct PoseRecord {
  Pose2 pose;      ///< yaw wrapped into (-pi, pi]
  double t = 0.0;  ///< seconds; 0 when the file has no t column
  /// "segment", "arc", "rotation", "clothoid" or a kind added later; empty without a kind
  /// column.
  std::string kind;
};

/// The rows of a pose file, and which optional columns it had.
struct PoseTable {
  std::vector<PoseRecord> rows;
  bool has_time = false;
  bool has_kind = false;
};

/// Reads pose files (`trajectory.csv`, `visited` files; docs/REFERENCE.md, File formats): a header
/// row naming the columns, `x`, `y`, `yaw` required, `t` and `kind` optional, any other
/// columns allowed and ignored, in any order. Fields are separated by commas (no quoting);
/// surrounding spaces, CRLF line ends and blank lines are accepted. Every problem is an
/// InvalidInputError naming the file, line and column: a missing or repeated column, a row
/// with the wrong number of fields, a non-numeric or non-finite number, a kind that is not
/// a name of lower-case letters, digits and underscores (an unknown kind is a curve
/// sampled densely enough), a decreasing t, no rows. Yaw may be any finite angle; it is
/// wrapped into (-pi, pi]. Limits: files of at most kMaxFileBytes and kMaxRows rows.
class PoseCsvReader {
 public:
  /// Largest file read, bytes.
  static constexpr std::size_t kMaxFileBytes = 512u << 20;
  /// Most rows read.
  static constexpr std::size_t kMaxRows = 5000000;

  /// Reads the file at `path`.
  PoseTable read(const std::string& path) const;

  /// The poses of the file at `path`, in file order (the trajectory of `evaluate` and
  /// `simulate`, the visited history of `replan`).
  std::vector<Pose2> readPoses(const std::string& path) const;

  /// Reads CSV text; `source_name` names it in messages.
  PoseTable parse(const std::string& text, const std::string& source_name) const;
};

}  // namespace kinematic_coverage::core
