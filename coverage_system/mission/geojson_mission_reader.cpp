#include "coverage_system/mission/geojson_mission_reader.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <tuple>
#include <utility>

#include "coverage_system/mission/local_east_north_frame.h"
#include "coverage_system/mission/mission_file_reader.h"
#include "coverage_system/mission/mission_frame.h"
#include "coverage_system/mission/yaml_parameter_reader.h"
#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/region_intersection.h"

namespace kinematic_coverage::core {
namespace {

/// A polygon in geographic coordinates: rings of (latitude, longitude), closing vertex
/// dropped.
struct GeoPolygon {
  std::vector<std::vector<GeoPoint>> rings;
};

/// Mean earth radius (m), for the extent that messages give.
constexpr double kEarthRadius = 6371000.0;

/// The hulls' extent in latitude and longitude, longitudes taken across the antimeridian
/// where the hulls straddle it (east may then exceed 180).
struct HullExtent {
  double south = 90.0;
  double north = -90.0;
  double west = INFINITY;
  double east = -INFINITY;

  /// The middle of the extent: the default datum, from which no vertex of a lake is
  /// farther than half its bounding box's diagonal.
  GeoPoint centre() const {
    const double longitude = std::remainder(0.5 * (west + east), 360.0);
    return {0.5 * (south + north), longitude == -180.0 ? 180.0 : longitude};
  }

  /// "spans 412 km east-west and 80 km north-south (longitude 3.1 to 8.6, latitude ...)".
  std::string description() const {
    const double radians = M_PI / 180.0;
    const double width =
        kEarthRadius * std::cos(0.5 * (south + north) * radians) * (east - west) * radians;
    const double height = kEarthRadius * (north - south) * radians;
    return "spans " + formatNumber(std::round(width / 1000.0)) + " km east-west and " +
           formatNumber(std::round(height / 1000.0)) + " km north-south (longitude " +
           formatNumber(std::remainder(west, 360.0)) + " to " +
           formatNumber(std::remainder(east, 360.0)) + ", latitude " + formatNumber(south) +
           " to " + formatNumber(north) + ")";
  }
};

/// The extent of the polygons' hulls. Throws InvalidInputError, naming the vertex as
/// projecting it would, for a hull vertex out of range.
HullExtent hullExtent(const std::vector<GeoPolygon>& polygons, const std::string& source_name) {
  const double reference = polygons.front().rings.front().front().longitude;
  HullExtent extent;
  for (std::size_t p = 0; p < polygons.size(); ++p) {
    if (polygons[p].rings.empty()) continue;
    const std::vector<GeoPoint>& hull = polygons[p].rings.front();
    for (std::size_t v = 0; v < hull.size(); ++v) {
      const GeoPoint& point = hull[v];
      LocalEastNorthFrame::checkRange(
          point, source_name + ": " +
                     (polygons.size() == 1 ? "" : "polygon " + std::to_string(p) + " ") +
                     "hull vertex " + std::to_string(v));
      // The longitude nearest the first vertex's, so that a hull across the antimeridian
      // keeps one extent.
      const double longitude = reference + std::remainder(point.longitude - reference, 360.0);
      extent.south = std::min(extent.south, point.latitude);
      extent.north = std::max(extent.north, point.latitude);
      extent.west = std::min(extent.west, longitude);
      extent.east = std::max(extent.east, longitude);
    }
  }
  return extent;
}

/// What the features of the collection hold, before projection.
struct GeoFeatures {
  std::vector<GeoPolygon> polygons;
  std::optional<GeoPoint> start;
  std::optional<GeoPoint> goal;
  std::optional<GeoPoint> datum;
  std::string frame_id = "map";
  /// The polygon properties that are parameters: name, value and where it is.
  std::vector<std::tuple<std::string, YAML::Node, std::string>> parameters;
};

class GeoJsonParser {
 public:
  explicit GeoJsonParser(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& where, const std::string& problem) const {
    throw InvalidInputError(source_ + ": " + (where.empty() ? "" : where + ": ") + problem);
  }

  GeoFeatures features(const YAML::Node& root) const {
    if (!root.IsMap() || !root["type"] || root["type"].Scalar() != "FeatureCollection") {
      fail("", "not a GeoJSON FeatureCollection (its \"type\" must be \"FeatureCollection\")");
    }
    const YAML::Node list = root["features"];
    if (!list || !list.IsSequence()) fail("features", "must be a list of features");
    GeoFeatures found;
    for (std::size_t i = 0; i < list.size(); ++i) feature(list[i], i, found);
    if (found.polygons.empty()) fail("", "no Polygon or MultiPolygon feature: the area is missing");
    if (!found.start) fail("", "no Point feature with \"role\": \"start\"");
    if (!found.goal) fail("", "no Point feature with \"role\": \"goal\"");
    return found;
  }

 private:
  void feature(const YAML::Node& node, std::size_t index, GeoFeatures& found) const {
    const std::string where = "features[" + std::to_string(index) + "]";
    if (!node.IsMap()) fail(where, "must be a Feature object");
    const YAML::Node geometry = node["geometry"];
    if (!geometry || !geometry.IsMap() || !geometry["type"]) {
      fail(where, "has no geometry with a \"type\"");
    }
    const std::string type = geometry["type"].Scalar();
    const YAML::Node coordinates = geometry["coordinates"];
    const YAML::Node properties = node["properties"];
    if (!coordinates) fail(where, "its geometry has no \"coordinates\"");
    if (type == "Polygon") {
      found.polygons.push_back(polygon(coordinates, where));
      polygonProperties(properties, where, found);
    } else if (type == "MultiPolygon") {
      if (!coordinates.IsSequence()) fail(where, "a MultiPolygon's coordinates must be a list");
      for (std::size_t k = 0; k < coordinates.size(); ++k) {
        found.polygons.push_back(
            polygon(coordinates[k], where + ".coordinates[" + std::to_string(k) + "]"));
      }
      polygonProperties(properties, where, found);
    } else if (type == "Point") {
      const std::string role =
          properties && properties.IsMap() && properties["role"] ? properties["role"].Scalar() : "";
      std::optional<GeoPoint>* slot = role == "start"  ? &found.start
                                      : role == "goal" ? &found.goal
                                                       : nullptr;
      if (slot == nullptr) {
        fail(where, "a Point feature needs the property \"role\": \"start\" or \"goal\"");
      }
      if (*slot) fail(where, "a second Point with \"role\": \"" + role + "\"");
      *slot = position(coordinates, where + ".coordinates");
    } else {
      fail(where,
           "a " + type + " geometry: a mission has Polygon, MultiPolygon and Point features");
    }
  }

  void polygonProperties(const YAML::Node& properties, const std::string& where,
                         GeoFeatures& found) const {
    if (!properties || properties.IsNull()) return;
    if (!properties.IsMap()) fail(where, "its properties must be an object");
    for (const auto& entry : properties) {
      const std::string key = entry.first.Scalar();
      const YAML::Node& value = entry.second;
      if (key == "datum") {
        if (!value.IsSequence() || value.size() != 2) {
          fail(where + ".properties.datum", "must be [latitude, longitude]");
        }
        found.datum = GeoPoint{number(value[0], where + ".properties.datum"),
                               number(value[1], where + ".properties.datum")};
      } else if (key == "frame_id") {
        found.frame_id = value.Scalar();
      } else {
        if (!value.IsScalar()) {
          fail(where + ".properties." + key, "a parameter must be a number, a name or a boolean");
        }
        found.parameters.emplace_back(key, value, source_ + ": " + where + ".properties");
      }
    }
  }

  double number(const YAML::Node& node, const std::string& where) const {
    double value = 0.0;
    if (!node.IsScalar() || !YAML::convert<double>::decode(node, value) || !std::isfinite(value)) {
      fail(where, "expected a finite number");
    }
    return value;
  }

  GeoPoint position(const YAML::Node& node, const std::string& where) const {
    if (!node.IsSequence() || node.size() < 2 || node.size() > 3) {
      fail(where, "a position must be [longitude, latitude] (or with an altitude)");
    }
    return GeoPoint{number(node[1], where), number(node[0], where)};
  }

  GeoPolygon polygon(const YAML::Node& node, const std::string& where) const {
    if (!node.IsSequence() || node.size() == 0) {
      fail(where, "a Polygon's coordinates must be a list of rings");
    }
    GeoPolygon result;
    for (std::size_t r = 0; r < node.size(); ++r) {
      const std::string ring_where = where + " ring " + std::to_string(r);
      if (!node[r].IsSequence()) fail(ring_where, "must be a list of positions");
      std::vector<GeoPoint> ring;
      for (std::size_t v = 0; v < node[r].size(); ++v) {
        ring.push_back(position(node[r][v], ring_where + " position " + std::to_string(v)));
      }
      // GeoJSON closes every ring by repeating its first position.
      if (ring.size() > 1 && ring.front().latitude == ring.back().latitude &&
          ring.front().longitude == ring.back().longitude) {
        ring.pop_back();
      }
      result.rings.push_back(std::move(ring));
    }
    return result;
  }

  std::string source_;
};

Ring projected(const std::vector<GeoPoint>& ring, const MissionFrame& frame,
               const std::string& what) {
  Ring local;
  for (std::size_t v = 0; v < ring.size(); ++v) {
    local.push_back(frame.toLocal(ring[v], what + " vertex " + std::to_string(v)));
  }
  return local;
}

/// The features' polygons, start and goal in `frame`, into `mission`. Throws
/// InvalidInputError for a point the frame does not reach (naming the area's extent) and
/// for polygons that do not make one area.
void projectFeatures(const GeoFeatures& features, const MissionFrame& frame,
                     const GeoJsonParser& parser, const std::string& source_name,
                     const HullExtent& extent, Mission& mission) {
  std::vector<PolygonWithHoles> areas;
  try {
    for (std::size_t p = 0; p < features.polygons.size(); ++p) {
      const GeoPolygon& polygon = features.polygons[p];
      const std::string name =
          features.polygons.size() == 1 ? "" : "polygon " + std::to_string(p) + " ";
      PolygonWithHoles area;
      area.hull = projected(polygon.rings.front(), frame, source_name + ": " + name + "hull");
      for (std::size_t h = 1; h < polygon.rings.size(); ++h) {
        area.holes.push_back(projected(
            polygon.rings[h], frame, source_name + ": " + name + "hole " + std::to_string(h - 1)));
      }
      areas.push_back(std::move(area));
    }
    mission.start = frame.toLocal(*features.start, source_name + ": the start");
    mission.goal = frame.toLocal(*features.goal, source_name + ": the goal");
  } catch (const InvalidInputError& error) {
    throw InvalidInputError(std::string(error.what()) + "; the area " + extent.description());
  }
  if (areas.size() == 1) {
    mission.polygon = std::move(areas.front());
    return;
  }
  const std::vector<PolygonWithHoles> united = unionOfAreas(areas);
  if (united.size() != 1) {
    parser.fail("", "its " + std::to_string(areas.size()) + " polygons make " +
                        std::to_string(united.size()) +
                        " separate areas: a mission covers one connected area");
  }
  mission.polygon = united.front();
}

}  // namespace

bool GeoJsonMissionReader::isGeoJsonPath(const std::string& path) {
  std::string lower = path;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  auto endsWith = [&](const std::string& suffix) {
    return lower.size() >= suffix.size() &&
           lower.compare(lower.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  return endsWith(".geojson") || endsWith(".json");
}

GeoJsonMissionReader::GeoJsonMissionReader(std::optional<GeoPoint> datum) : datum_(datum) {}

Mission GeoJsonMissionReader::read(const std::string& path,
                                   const std::vector<std::string>& overrides,
                                   const PlannerParameters& base) const {
  return parse(MissionFileReader::readText(path), path, overrides, base);
}

Mission GeoJsonMissionReader::parse(const std::string& text, const std::string& source_name,
                                    const std::vector<std::string>& overrides,
                                    const PlannerParameters& base) const {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& error) {
    throw InvalidInputError(source_name + ": not valid JSON: " + error.msg);
  }
  const GeoJsonParser parser(source_name);
  const GeoFeatures features = parser.features(root);
  const GeoPolygon& first = features.polygons.front();
  if (first.rings.empty() || first.rings.front().empty())
    parser.fail("", "the hull has no vertices");
  const HullExtent extent = hullExtent(features.polygons, source_name);

  Mission mission;
  mission.frame_id = features.frame_id;
  mission.parameters = base;
  YamlParameterReader parameters(mission.parameters);
  for (const auto& [name, value, where] : features.parameters) parameters.set(name, value, where);
  for (const std::string& assignment : overrides) parameters.setAssignment(assignment);
  parameters.check();
  const MissionFrame frame = MissionFrame::of(datum_           ? *datum_
                                              : features.datum ? *features.datum
                                                               : extent.centre(),
                                              mission.parameters);
  mission.datum = frame.datum();
  projectFeatures(features, frame, parser, source_name, extent, mission);
  return mission;
}

}  // namespace kinematic_coverage::core
