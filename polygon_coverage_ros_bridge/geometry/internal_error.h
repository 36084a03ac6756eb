#pragma once

#include <stdexcept>
#include <string>

namespace kinematic_coverage::core {

/// Thrown when a stage fails on input that passed validation: a bug of the package, not
/// the user's fault (docs/REFERENCE.md, coverage_tool, Exit status). The message names the
/// stage; boundaries report it as an internal error (exit 1, ROS_ERROR) and never as
/// input to change.
class InternalError : public std::runtime_error {
 public:
  InternalError(const std::string& stage, const std::string& message)
      : std::runtime_error("the " + stage + " stage failed on valid input: " + message),
        stage_(stage) {}

  /// The stage that failed ("offset", "sweeps", "transitions", ...).
  const std::string& stage() const { return stage_; }

 private:
  std::string stage_;
};

}  // namespace kinematic_coverage::core
