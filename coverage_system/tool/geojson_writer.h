#pragma once

#include <string>
#include <vector>

#include "coverage_system/mission/mission.h"
#include "coverage_system/mission/mission_frame.h"
#include "coverage_system/tool/json_object.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// Writes the GeoJSON of geo-referenced missions (docs/REFERENCE.md, File formats):
/// FeatureCollections in WGS84, positions [longitude, latitude], rings closed and oriented
/// as RFC 7946 asks (hull counter-clockwise, holes clockwise).
class GeoJsonWriter {
 public:
  /// Decimals of the degrees of plan outputs' positions: 1e-7 degrees, about 1 cm.
  static constexpr int kOutputDecimals = 7;

  explicit GeoJsonWriter(const MissionFrame& frame) : frame_(frame) {}

  /// Sets the frame a plan was made in: the `datum` [latitude, longitude], the
  /// `projection` and, for `utm`, the `utm_zone` (metrics.json and the GeoJSON outputs).
  static void setFrame(const MissionFrame& frame, JsonObject& properties);

  /// One LineString feature through the local `points`, positions rounded to
  /// kOutputDecimals (1e-7 degrees, about a centimetre), with `name`, the per-vertex `times`
  /// (s, one per point), the `frame_id` and the frame (setFrame) in its properties:
  /// waypoints.geojson, trajectory.geojson.
  std::string lineString(const std::vector<Point2>& points, const std::vector<double>& times,
                         const std::string& name, const std::string& frame_id) const;

  /// The mission's area as a Polygon feature (the datum as its `datum` property,
  /// [latitude, longitude], and every parameter that differs from its default as a
  /// property) and its start and goal as Point features with their `role`, positions in the
  /// shortest form that reads back exactly: what `coverage_tool export` writes and
  /// GeoJsonMissionReader reads back.
  /// Without `with_datum` the `datum` property is left out, so that the reader anchors the
  /// frame at its default datum, the centre of the area's extent.
  std::string mission(const Mission& mission, bool with_datum = true) const;

 private:
  std::string exactPosition(const Point2& local) const;
  std::string ring(const Ring& ring, bool counter_clockwise) const;

  MissionFrame frame_;
};

}  // namespace kinematic_coverage::core
