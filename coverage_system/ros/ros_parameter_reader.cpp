#include "coverage_system/ros/ros_parameter_reader.h"

#include <xmlrpcpp/XmlRpcValue.h>

#include <optional>
#include <string>

#include "coverage_system/mission/mission_file_reader.h"
#include "coverage_system/mission/read_mission.h"
#include "coverage_system/parameters/parameter_schema.h"
#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::nodes {
namespace {

/// A parameter server value as a parameter's value: a boolean, a number (an integer or a
/// double) or a name.
core::ParameterValue parameterValueOf(const std::string& where, XmlRpc::XmlRpcValue& value) {
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      return static_cast<bool>(value);
    case XmlRpc::XmlRpcValue::TypeInt:
      return static_cast<double>(static_cast<int>(value));
    case XmlRpc::XmlRpcValue::TypeDouble:
      return static_cast<double>(value);
    case XmlRpc::XmlRpcValue::TypeString:
      return static_cast<std::string>(value);
    default:
      throw core::InvalidInputError(where + " must be a number, a name or true/false");
  }
}

/// The type of a parameter server value, as a user would name it.
std::string typeName(XmlRpc::XmlRpcValue& value) {
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      return "a boolean (" + std::string(static_cast<bool>(value) ? "true" : "false") + ")";
    case XmlRpc::XmlRpcValue::TypeInt:
      return "an integer (" + std::to_string(static_cast<int>(value)) + ")";
    case XmlRpc::XmlRpcValue::TypeDouble:
      return "a double (" + core::formatRoundTrip(static_cast<double>(value)) + ")";
    case XmlRpc::XmlRpcValue::TypeString:
      return "a string ('" + static_cast<std::string>(value) + "')";
    case XmlRpc::XmlRpcValue::TypeArray:
      return "a list";
    case XmlRpc::XmlRpcValue::TypeStruct:
      return "a dictionary";
    default:
      return "a value of another type";
  }
}

[[noreturn]] void wrongType(const ros::NodeHandle& node, const std::string& name,
                            const std::string& expected, XmlRpc::XmlRpcValue& value) {
  throw core::InvalidInputError("parameter " + node.resolveName(name) + " must be " + expected +
                                ", not " + typeName(value));
}

/// A number parameter's value, an integer or a double; nothing for another type.
std::optional<double> numberOf(XmlRpc::XmlRpcValue& value) {
  if (value.getType() == XmlRpc::XmlRpcValue::TypeDouble) return static_cast<double>(value);
  if (value.getType() == XmlRpc::XmlRpcValue::TypeInt) return static_cast<int>(value);
  return std::nullopt;
}

}  // namespace

double readNumberParameter(const ros::NodeHandle& node, const std::string& name,
                           double default_value) {
  XmlRpc::XmlRpcValue value;
  if (!node.getParam(name, value)) return default_value;
  if (const std::optional<double> number = numberOf(value)) return *number;
  wrongType(node, name, "a number (double)", value);
}

bool readFlagParameter(const ros::NodeHandle& node, const std::string& name, bool default_value) {
  XmlRpc::XmlRpcValue value;
  if (!node.getParam(name, value)) return default_value;
  if (value.getType() == XmlRpc::XmlRpcValue::TypeBoolean) return static_cast<bool>(value);
  wrongType(node, name, "true or false (bool)", value);
}

std::string readStringParameter(const ros::NodeHandle& node, const std::string& name,
                                const std::string& default_value) {
  XmlRpc::XmlRpcValue value;
  if (!node.getParam(name, value)) return default_value;
  if (value.getType() == XmlRpc::XmlRpcValue::TypeString) return static_cast<std::string>(value);
  wrongType(node, name, "a string", value);
}

std::optional<core::GeoPoint> readGeoPointParameter(const ros::NodeHandle& node,
                                                    const std::string& name) {
  XmlRpc::XmlRpcValue value;
  if (!node.getParam(name, value)) return std::nullopt;
  const std::string expected = "[latitude, longitude] (two numbers, WGS84 degrees)";
  if (value.getType() != XmlRpc::XmlRpcValue::TypeArray || value.size() != 2) {
    wrongType(node, name, expected, value);
  }
  const std::optional<double> latitude = numberOf(value[0]);
  const std::optional<double> longitude = numberOf(value[1]);
  if (!latitude || !longitude) wrongType(node, name, expected, value);
  return core::GeoPoint{*latitude, *longitude};
}

core::PlannerParameters readPlannerParameters(const ros::NodeHandle& private_node) {
  core::PlannerParameters parameters;
  const std::string config = readStringParameter(private_node, "config", "");
  if (!config.empty()) parameters = core::MissionFileReader().readParameters(config);
  const std::string mission = readStringParameter(private_node, "mission", "");
  if (!mission.empty()) parameters = core::readMission(mission, {}, parameters).parameters;
  core::ParameterOrigins origins;
  for (const core::ParameterDeclaration& declaration : core::parameterSchema()) {
    XmlRpc::XmlRpcValue value;
    if (!private_node.getParam(declaration.name, value)) continue;
    const std::string where = "parameter " + private_node.resolveName(declaration.name);
    core::assignParameter(parameters, declaration, parameterValueOf(where, value), where);
    origins[declaration.name] = where;
  }
  core::checkParameters(parameters, origins);
  return parameters;
}

}  // namespace kinematic_coverage::nodes
