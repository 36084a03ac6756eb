#pragma once

#include <stdexcept>
#include <string>

namespace kinematic_coverage::core {

/// Thrown for input the package rejects (docs/REFERENCE.md, Geometry and input rules): bad
/// geometry, parameters out of range, an impossible request. The message names the problem
/// precisely; boundaries (coverage_tool, nodes) catch it and report it (exit 2, ROS_ERROR).
class InvalidInputError : public std::runtime_error {
 public:
  explicit InvalidInputError(const std::string& message) : std::runtime_error(message) {}
};

/// Thrown for input over one of the documented size limits (docs/REFERENCE.md, Size
/// limits): the user's to change (a simpler polygon, a coarser sampling) however late in
/// the pipeline it shows, so boundaries never report it as an internal error.
class SizeLimitError : public InvalidInputError {
 public:
  explicit SizeLimitError(const std::string& message) : InvalidInputError(message) {}
};

/// Thrown for a goal that a robot keeping the gap clearance cannot reach from the start
/// (docs/REFERENCE.md, Geometry and input rules, Parts): the request is impossible as set,
/// not the map invalid; benchmarks count such maps apart.
class UnreachableGoalError : public InvalidInputError {
 public:
  explicit UnreachableGoalError(const std::string& message) : InvalidInputError(message) {}
};

}  // namespace kinematic_coverage::core
