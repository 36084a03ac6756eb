#pragma once

#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {

/// Writes `text` to `path`, replacing the file. A file that cannot be written (missing
/// directory, no permission, full disk) is an impossible request: InvalidInputError.
inline void writeTextFile(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (out) out << text;
  if (out) out.flush();
  if (!out) {
    throw InvalidInputError("cannot write " + path + ": " + std::strerror(errno));
  }
}

}  // namespace kinematic_coverage::core
