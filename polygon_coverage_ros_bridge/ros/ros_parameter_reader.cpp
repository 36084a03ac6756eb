#include "polygon_coverage_ros_bridge/ros/ros_parameter_reader.h"

#include <xmlrpcpp/XmlRpcValue.h>

#include <sstream>
#include <string>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/mission/mission_file_reader.h"
#include "polygon_coverage_ros_bridge/mission/round_trip_number.h"

namespace kinematic_coverage::nodes {
namespace {

/// A parameter server value as the YAML scalar a mission file would hold.
std::string asYamlScalar(const std::string& name, XmlRpc::XmlRpcValue& value) {
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      return static_cast<bool>(value) ? "true" : "false";
    case XmlRpc::XmlRpcValue::TypeInt:
      return std::to_string(static_cast<int>(value));
    case XmlRpc::XmlRpcValue::TypeDouble:
      return core::formatRoundTrip(static_cast<double>(value));
    case XmlRpc::XmlRpcValue::TypeString:
      return static_cast<std::string>(value);
    default:
      throw core::InvalidInputError("parameter ~" + name +
                                    " must be a number, a name or true/false");
  }
}

}  // namespace

core::PlannerParameters readPlannerParameters(const ros::NodeHandle& private_node) {
  std::vector<std::string> overrides;
  for (const std::string& name : core::MissionFileReader::parameterNames()) {
    XmlRpc::XmlRpcValue value;
    if (!private_node.getParam(name, value)) continue;
    overrides.push_back(name + "=" + asYamlScalar(name, value));
  }
  return core::MissionFileReader().withOverrides(core::PlannerParameters(), overrides);
}

}  // namespace kinematic_coverage::nodes
