#include "coverage_system/mission/mission_file_reader.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "coverage_system/mission/yaml_parameter_reader.h"
#include "coverage_system/parameters/parameter_schema.h"
#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/validation/polygon_validator.h"

namespace kinematic_coverage::core {
namespace {

/// A YAML value as messages name it.
constexpr auto kindOf = &YamlParameterReader::kindOf;

/// Reads YAML nodes, naming the source and line of each problem.
class NodeReader {
 public:
  explicit NodeReader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const YAML::Node& node, const std::string& where,
                         const std::string& problem) const {
    std::string location = source_;
    if (node.Mark().line >= 0) location += ":" + std::to_string(node.Mark().line + 1);
    throw InvalidInputError(location + ": " + where + ": " + problem);
  }

  double number(const YAML::Node& node, const std::string& where, const std::string& what) const {
    if (!node.IsScalar()) fail(node, where, what + " must be a number, not " + kindOf(node));
    double value = 0.0;
    if (!YAML::convert<double>::decode(node, value)) {
      fail(node, where, what + " " + kindOf(node) + " is not a number");
    }
    if (!std::isfinite(value)) fail(node, where, what + " " + kindOf(node) + " is not finite");
    return value;
  }

  Point2 point(const YAML::Node& node, const std::string& where) const {
    if (!node.IsSequence() || node.size() != 2) {
      fail(node, where,
           "a point must be a list of 2 numbers [x, y], not " +
               (node.IsSequence() ? "a list of " + std::to_string(node.size()) +
                                        (node.size() == 1 ? " item" : " items")
                                  : kindOf(node)));
    }
    const Point2 p(number(node[0], where, "the x coordinate"),
                   number(node[1], where, "the y coordinate"));
    for (int axis = 0; axis < 2; ++axis) {
      if (std::abs(p[axis]) > kMaxCoordinateMagnitude) {
        fail(node, where,
             std::string("the ") + (axis == 0 ? "x" : "y") + " coordinate " +
                 formatNumber(p[axis]) + " exceeds the limit of +-" +
                 formatNumber(kMaxCoordinateMagnitude) + " m");
      }
    }
    return p;
  }

  Ring ring(const YAML::Node& node, const std::string& where, std::size_t& vertex_budget) const {
    if (!node.IsSequence()) {
      fail(node, where, "a ring must be a list of [x, y] points, not " + kindOf(node));
    }
    if (node.size() > vertex_budget) {
      fail(node, where,
           "the polygon has more than " + std::to_string(kMaxTotalVertices) +
               " vertices in total, the limit");
    }
    vertex_budget -= node.size();
    Ring result;
    result.reserve(node.size());
    for (std::size_t i = 0; i < node.size(); ++i) {
      result.push_back(point(node[i], where + "[" + std::to_string(i) + "]"));
    }
    return result;
  }

  PolygonWithHoles polygon(const YAML::Node& node, const std::string& where) const {
    if (!node.IsMap()) fail(node, where, "must be a map with hull and holes, not " + kindOf(node));
    PolygonWithHoles result;
    std::size_t vertex_budget = kMaxTotalVertices;
    bool has_hull = false;
    for (const auto& [key, value] : entries(node, where)) {
      if (key == "hull") {
        result.hull = ring(value, where + ".hull", vertex_budget);
        has_hull = true;
      } else if (key == "holes") {
        if (value.IsNull()) continue;
        if (!value.IsSequence()) {
          fail(value, where + ".holes", "must be a list of rings, not " + kindOf(value));
        }
        if (value.size() > kMaxHoles) {
          fail(value, where + ".holes",
               std::to_string(value.size()) + " holes, more than the limit of " +
                   std::to_string(kMaxHoles));
        }
        for (std::size_t h = 0; h < value.size(); ++h) {
          result.holes.push_back(
              ring(value[h], where + ".holes[" + std::to_string(h) + "]", vertex_budget));
        }
      } else {
        fail(value, where + "." + key, "unknown key (a polygon has hull and holes)");
      }
    }
    if (!has_hull) fail(node, where, "the hull is missing");
    return result;
  }

  /// The entries of a map in file order; keys must be distinct scalars.
  std::vector<std::pair<std::string, YAML::Node>> entries(const YAML::Node& map,
                                                          const std::string& where) const {
    std::vector<std::pair<std::string, YAML::Node>> result;
    std::set<std::string> seen;
    for (const auto& entry : map) {
      const std::string prefix = where.empty() ? "" : where + ".";
      if (!entry.first.IsScalar()) fail(entry.first, where, "a key must be a name");
      const std::string key = entry.first.Scalar();
      if (!seen.insert(key).second) fail(entry.first, prefix + key, "the key appears twice");
      result.emplace_back(key, entry.second);
    }
    return result;
  }

  /// Where `node` is: the source and its line.
  std::string location(const YAML::Node& node) const {
    return node.Mark().line >= 0 ? source_ + ":" + std::to_string(node.Mark().line + 1) : source_;
  }

 private:
  std::string source_;
};

YAML::Node loadYaml(const std::string& text, const std::string& source_name) {
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& error) {
    std::string location = source_name;
    if (error.mark.line >= 0) location += ":" + std::to_string(error.mark.line + 1);
    throw InvalidInputError(location + ": not valid YAML: " + error.msg);
  }
}

YAML::Node rootMap(const std::string& text, const std::string& source_name) {
  const YAML::Node root = loadYaml(text, source_name);
  if (root.IsNull()) throw InvalidInputError(source_name + ": the file is empty");
  if (!root.IsMap()) {
    throw InvalidInputError(source_name + ": the file must be a map of keys, not " + kindOf(root));
  }
  return root;
}

}  // namespace

std::string MissionFileReader::readText(const std::string& path) {
  std::error_code code;
  const auto status = std::filesystem::status(path, code);
  if (code || !std::filesystem::exists(status)) {
    throw InvalidInputError(path + ": no such file");
  }
  if (!std::filesystem::is_regular_file(status)) {
    throw InvalidInputError(path + ": not a regular file");
  }
  const auto size = std::filesystem::file_size(path, code);
  if (!code && size > kMaxMissionFileBytes) {
    throw InvalidInputError(path + ": " + std::to_string(size) + " bytes, more than the limit of " +
                            std::to_string(kMaxMissionFileBytes));
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw InvalidInputError(path + ": cannot be read");
  return text.str();
}

Mission MissionFileReader::read(const std::string& path, const std::vector<std::string>& overrides,
                                const PlannerParameters& base) const {
  return parse(readText(path), path, overrides, base);
}

Mission MissionFileReader::parse(const std::string& yaml_text, const std::string& source_name,
                                 const std::vector<std::string>& overrides,
                                 const PlannerParameters& base) const {
  const YAML::Node root = rootMap(yaml_text, source_name);
  const NodeReader reader(source_name);
  Mission mission;
  mission.parameters = base;
  YamlParameterReader parameters(mission.parameters);
  bool has_polygon = false, has_start = false, has_goal = false;
  for (const auto& [key, value] : reader.entries(root, "")) {
    if (key == "frame_id") {
      if (!value.IsScalar() || value.Scalar().empty()) {
        reader.fail(value, key, "must be a frame name, not " + kindOf(value));
      }
      mission.frame_id = value.Scalar();
    } else if (key == "polygon") {
      mission.polygon = reader.polygon(value, key);
      has_polygon = true;
    } else if (key == "start") {
      mission.start = reader.point(value, key);
      has_start = true;
    } else if (key == "goal") {
      mission.goal = reader.point(value, key);
      has_goal = true;
    } else if (const ParameterDeclaration* declaration = findParameter(key)) {
      parameters.set(*declaration, value, reader.location(value));
    } else {
      reader.fail(value, key,
                  "unknown key (a mission has frame_id, polygon, start, goal and the "
                  "parameters of config/default.yaml)");
    }
  }
  if (!has_polygon) throw InvalidInputError(source_name + ": the polygon is missing");
  if (!has_start) throw InvalidInputError(source_name + ": the start is missing");
  if (!has_goal) throw InvalidInputError(source_name + ": the goal is missing");
  for (const std::string& assignment : overrides) parameters.setAssignment(assignment);
  parameters.check();
  return mission;
}

PolygonWithHoles MissionFileReader::readUpdatedPolygon(const std::string& path) const {
  return parseUpdatedPolygon(readText(path), path);
}

PolygonWithHoles MissionFileReader::parseUpdatedPolygon(const std::string& yaml_text,
                                                        const std::string& source_name) const {
  const YAML::Node root = rootMap(yaml_text, source_name);
  const NodeReader reader(source_name);
  PolygonWithHoles polygon;
  bool has_polygon = false;
  for (const auto& [key, value] : reader.entries(root, "")) {
    if (key == "polygon") {
      polygon = reader.polygon(value, key);
      has_polygon = true;
    } else if (key != "frame_id") {
      reader.fail(value, key, "unknown key (an updated polygon file has polygon and frame_id)");
    }
  }
  if (!has_polygon) throw InvalidInputError(source_name + ": the polygon is missing");
  return polygon;
}

PlannerParameters MissionFileReader::readParameters(const std::string& path) const {
  const YAML::Node root = rootMap(readText(path), path);
  const NodeReader reader(path);
  PlannerParameters parameters;
  YamlParameterReader parameter_reader(parameters);
  for (const auto& [key, value] : reader.entries(root, "")) {
    const ParameterDeclaration* declaration = findParameter(key);
    if (declaration == nullptr) reader.fail(value, key, "unknown parameter");
    parameter_reader.set(*declaration, value, reader.location(value));
  }
  parameter_reader.check();
  return parameters;
}

PlannerParameters MissionFileReader::withOverrides(
    PlannerParameters parameters, const std::vector<std::string>& overrides) const {
  YamlParameterReader parameter_reader(parameters);
  for (const std::string& assignment : overrides) parameter_reader.setAssignment(assignment);
  parameter_reader.check();
  return parameters;
}

std::string MissionFileReader::parameterText(const PlannerParameters& parameters,
                                             const std::string& name) {
  const ParameterDeclaration* declaration = findParameter(name);
  if (declaration == nullptr) throw InvalidInputError("unknown parameter '" + name + "'");
  return parameterValueText(*declaration, parameterValue(parameters, *declaration));
}

std::vector<std::string> MissionFileReader::parameterNames() {
  std::vector<std::string> names;
  for (const ParameterDeclaration& declaration : parameterSchema()) {
    names.emplace_back(declaration.name);
  }
  return names;
}

}  // namespace kinematic_coverage::core
