#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace kinematic_coverage::core {

/// `coverage_tool parameters [--markdown]`: every parameter as the parameter schema declares
/// it. Without options, config/default.yaml (each parameter with its default, unit, range,
/// description and source); with --markdown, a table of name, unit, default, valid values,
/// stage and description.
class ParametersCommand {
 public:
  /// Usage text of the command.
  static std::string usage();

  /// Runs the command on its arguments (those after "parameters"). Throws InvalidInputError
  /// for an unknown option.
  void run(const std::vector<std::string>& args, std::ostream& out) const;
};

}  // namespace kinematic_coverage::core
