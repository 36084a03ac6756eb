#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

#include "polygon_coverage_ros_bridge/parameters/parameter_schema.h"

namespace kinematic_coverage::core {

/// Sets parameters from YAML values (a mission file's keys, a GeoJSON polygon's properties,
/// `--set`'s values) as their declarations in the parameter schema say, and records where
/// each value came from. Every problem is an InvalidInputError starting with that origin,
/// e.g. "lake.yaml:7: turning_radius: the value 'abc' is not a number" or "--set
/// lateral_overlap=1: lateral_overlap = 1 is out of range: it must be in [0, 1)".
class YamlParameterReader {
 public:
  YamlParameterReader(PlannerParameters& parameters, ParameterOrigins& origins)
      : parameters_(parameters), origins_(origins) {}

  /// Sets parameter `declaration` to `value`.
  void set(const ParameterDeclaration& declaration, const YAML::Node& value,
           const std::string& origin);

  /// A YAML value as messages name it: "'abc'", "a list", "a map" or "nothing".
  static std::string kindOf(const YAML::Node& node);

  /// Applies "name=value" (the value read as a YAML scalar), whose origin is `--set` and
  /// the assignment.
  void setAssignment(const std::string& assignment);

 private:
  PlannerParameters& parameters_;
  ParameterOrigins& origins_;
};

}  // namespace kinematic_coverage::core
