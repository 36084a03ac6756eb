#include "coverage_system/mission/yaml_parameter_reader.h"

#include <cmath>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {
namespace {

/// `node` as the value of `declaration`; throws InvalidInputError naming `where` for a
/// value of the wrong kind.
ParameterValue valueOf(const ParameterDeclaration& declaration, const YAML::Node& node,
                       const std::string& where) {
  const auto fail = [&](const std::string& problem) {
    throw InvalidInputError(where + ": " + declaration.name + ": " + problem);
  };
  if (std::holds_alternative<double PlannerParameters::*>(declaration.member)) {
    if (declaration.word != nullptr && node.IsScalar() && node.Scalar() == declaration.word) {
      return std::string(declaration.word);
    }
    if (!node.IsScalar())
      fail("the value must be a number, not " + YamlParameterReader::kindOf(node));
    double value = 0.0;
    if (!YAML::convert<double>::decode(node, value)) {
      fail("the value " + YamlParameterReader::kindOf(node) + " is not a number" +
           (declaration.word != nullptr ? std::string(" or the word ") + declaration.word
                                        : std::string()));
    }
    if (!std::isfinite(value))
      fail("the value " + YamlParameterReader::kindOf(node) + " is not finite");
    return value;
  }
  if (std::holds_alternative<bool PlannerParameters::*>(declaration.member)) {
    bool value = false;
    if (!node.IsScalar() || !YAML::convert<bool>::decode(node, value)) {
      fail("the value " + YamlParameterReader::kindOf(node) + " is not true or false");
    }
    return value;
  }
  if (!node.IsScalar()) fail("the value must be a name, not " + YamlParameterReader::kindOf(node));
  return node.Scalar();
}

}  // namespace

std::string YamlParameterReader::kindOf(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Map:
      return "a map";
    case YAML::NodeType::Scalar:
      return "'" + node.Scalar() + "'";
    default:
      return "nothing";
  }
}

void YamlParameterReader::set(const ParameterDeclaration& declaration, const YAML::Node& value,
                              const std::string& origin) {
  assignParameter(parameters_, declaration, valueOf(declaration, value, origin), origin);
  origins_[declaration.name] = origin;
}

void YamlParameterReader::set(const std::string& name, const YAML::Node& value,
                              const std::string& origin) {
  const ParameterDeclaration* declaration = findParameter(name);
  if (declaration == nullptr) {
    throw InvalidInputError(origin + ": unknown parameter '" + name + "'");
  }
  set(*declaration, value, origin);
}

void YamlParameterReader::setAssignment(const std::string& assignment) {
  const std::string origin = "--set " + assignment;
  const std::size_t equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0) {
    throw InvalidInputError(origin + ": expected name=value");
  }
  const std::string name = assignment.substr(0, equals);
  if (findParameter(name) == nullptr) {
    throw InvalidInputError(origin + ": unknown parameter '" + name + "'");
  }
  YAML::Node value;
  try {
    value = YAML::Load(assignment.substr(equals + 1));
  } catch (const YAML::Exception& error) {
    throw InvalidInputError(origin + ": not valid YAML: " + error.msg);
  }
  set(name, value, origin);
}

}  // namespace kinematic_coverage::core
