#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

#include "coverage_system/parameters/parameter_schema.h"

namespace kinematic_coverage::core {

/// Sets parameters from YAML values (a mission file's keys, a GeoJSON polygon's properties,
/// `--set`'s values) as their declarations in the parameter schema say, records where each
/// value came from, and checks the set once all are in. Every problem is an InvalidInputError
/// starting with that origin, e.g. "lake.yaml:7: turning_radius: the value 'abc' is not a number"
/// or "--set lateral_overlap=1: lateral_overlap = 1 is out of range: it must be in [0, 1)".
class YamlParameterReader {
 public:
  /// Sets values in `parameters`, which must outlive the reader.
  explicit YamlParameterReader(PlannerParameters& parameters) : parameters_(parameters) {}

  /// Sets parameter `declaration` to `value`.
  void set(const ParameterDeclaration& declaration, const YAML::Node& value,
           const std::string& origin);

  /// Sets the parameter `name` to `value`; InvalidInputError "ORIGIN: unknown parameter
  /// 'name'" when there is none.
  void set(const std::string& name, const YAML::Node& value, const std::string& origin);

  /// A YAML value as messages name it: "'abc'", "a list", "a map" or "nothing".
  static std::string kindOf(const YAML::Node& node);

  /// Applies "name=value" (the value read as a YAML scalar), whose origin is `--set` and
  /// the assignment.
  void setAssignment(const std::string& assignment);

  /// Checks the whole set (checkParameters), naming where the values out of range came
  /// from.
  void check() const { checkParameters(parameters_, origins_); }

 private:
  PlannerParameters& parameters_;
  ParameterOrigins origins_;
};

}  // namespace kinematic_coverage::core
