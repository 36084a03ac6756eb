#pragma once

#include <string>

#include "coverage_system/mission/mission.h"

namespace kinematic_coverage::core {

/// Writes a mission as a mission file (docs/REFERENCE.md, File formats) that
/// MissionFileReader reads back to the same mission: `frame_id`, the polygon, start and
/// goal with every coordinate in the shortest text that reads back exactly, and each
/// parameter whose value differs from the built-in default, so that a saved mission keeps
/// what was changed and plans as it did (`coverage_tool plan`, `mission.launch`).
class MissionFileWriter {
 public:
  /// The mission file's text; `comment` (one line, may be empty) heads it as a YAML comment.
  static std::string text(const Mission& mission, const std::string& comment);

  /// Writes text(mission, comment) to `path`, replacing the file. Throws InvalidInputError
  /// naming the path when it cannot be written.
  static void write(const Mission& mission, const std::string& path, const std::string& comment);
};

}  // namespace kinematic_coverage::core
