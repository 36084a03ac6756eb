#include "coverage_system/tool/geojson_writer.h"

#include <algorithm>
#include <charconv>

#include "coverage_system/mission/mission_file_reader.h"
#include "coverage_system/tool/json_object.h"
#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// A parameter's text as a JSON value: numbers and booleans bare, names quoted.
std::string parameterJson(const std::string& text) {
  if (text == "true" || text == "false") return text;
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error == std::errc() && end == text.data() + text.size()) return text;
  return jsonString(text);
}

std::string collection(const std::vector<std::string>& features) {
  std::string json = "{\"type\": \"FeatureCollection\", \"features\": [";
  for (std::size_t i = 0; i < features.size(); ++i)
    json += (i > 0 ? ",\n  " : "\n  ") + features[i];
  return json + "\n]}\n";
}

std::string feature(const JsonObject& properties, const std::string& geometry) {
  return "{\"type\": \"Feature\", \"properties\": " + properties.toString() +
         ", \"geometry\": " + geometry + "}";
}

}  // namespace

void GeoJsonWriter::setFrame(const MissionFrame& frame, JsonObject& properties) {
  properties.set("datum", std::vector<double>{frame.datum().latitude, frame.datum().longitude})
      .set("projection", frame.projectionName());
  if (const std::optional<std::string> zone = frame.utmZone()) properties.set("utm_zone", *zone);
}

std::string GeoJsonWriter::exactPosition(const Point2& local) const {
  const GeoPoint point = frame_.toGeographic(local);
  return "[" + formatRoundTrip(point.longitude) + ", " + formatRoundTrip(point.latitude) + "]";
}

std::string GeoJsonWriter::ring(const Ring& ring, bool counter_clockwise) const {
  Ring oriented = ring;
  if ((signedArea(oriented) > 0.0) != counter_clockwise) {
    std::reverse(oriented.begin(), oriented.end());
  }
  std::string json = "[";
  for (const Point2& p : oriented) json += exactPosition(p) + ", ";
  return json + exactPosition(oriented.front()) + "]";
}

std::string GeoJsonWriter::lineString(const std::vector<Point2>& points,
                                      const std::vector<double>& times, const std::string& name,
                                      const std::string& frame_id) const {
  if (points.size() != times.size()) {
    throw InvalidInputError("GeoJSON line string: " + std::to_string(points.size()) +
                            " points but " + std::to_string(times.size()) + " times");
  }
  std::string coordinates = "[";
  for (std::size_t i = 0; i < points.size(); ++i) {
    const GeoPoint point = frame_.toGeographic(points[i]);
    coordinates += std::string(i > 0 ? ", " : "") + "[" +
                   formatRoundTrip(roundToDecimals(point.longitude, kOutputDecimals)) + ", " +
                   formatRoundTrip(roundToDecimals(point.latitude, kOutputDecimals)) + "]";
  }
  JsonObject properties;
  properties.set("name", name).set("times", times).set("frame_id", frame_id);
  setFrame(frame_, properties);
  return collection(
      {feature(properties, "{\"type\": \"LineString\", \"coordinates\": " + coordinates + "]}")});
}

std::string GeoJsonWriter::mission(const Mission& mission, bool with_datum) const {
  JsonObject area;
  if (with_datum) {
    area.set("datum", std::vector<double>{frame_.datum().latitude, frame_.datum().longitude});
  }
  if (mission.frame_id != "map") area.set("frame_id", mission.frame_id);
  const PlannerParameters defaults;
  for (const std::string& name : MissionFileReader::parameterNames()) {
    const std::string text = MissionFileReader::parameterText(mission.parameters, name);
    if (text != MissionFileReader::parameterText(defaults, name)) {
      area.setJson(name, parameterJson(text));
    }
  }
  std::string rings = "[" + ring(mission.polygon.hull, true);
  for (const Ring& hole : mission.polygon.holes) rings += ", " + ring(hole, false);
  rings += "]";
  JsonObject start;
  start.set("role", std::string("start"));
  JsonObject goal;
  goal.set("role", std::string("goal"));
  return collection(
      {feature(area, "{\"type\": \"Polygon\", \"coordinates\": " + rings + "}"),
       feature(start,
               "{\"type\": \"Point\", \"coordinates\": " + exactPosition(mission.start) + "}"),
       feature(goal,
               "{\"type\": \"Point\", \"coordinates\": " + exactPosition(mission.goal) + "}")});
}

}  // namespace kinematic_coverage::core
