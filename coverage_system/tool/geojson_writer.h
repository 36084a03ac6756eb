#pragma once

#include <string>
#include <vector>

#include "coverage_system/mission/local_east_north_frame.h"
#include "coverage_system/mission/mission.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// The projection name of the local east-north frame, as metrics.json and the GeoJSON
/// outputs give it.
constexpr const char* kLocalProjection = "local";

/// Writes the GeoJSON of geo-referenced missions (docs/REFERENCE.md, File formats):
/// FeatureCollections in WGS84, positions [longitude, latitude] in the shortest form that
/// reads back exactly, rings closed and oriented as RFC 7946 asks (hull counter-clockwise,
/// holes clockwise).
class GeoJsonWriter {
 public:
  explicit GeoJsonWriter(const LocalEastNorthFrame& frame) : frame_(frame) {}

  /// One LineString feature through the local `points`, with `name`, the per-vertex
  /// `times` (s, one per point) and the frame they were planned in (`frame_id`, the
  /// `datum` [latitude, longitude] and the `projection`, "local": the local east-north
  /// frame) in its properties: waypoints.geojson, trajectory.geojson.
  std::string lineString(const std::vector<Point2>& points, const std::vector<double>& times,
                         const std::string& name, const std::string& frame_id) const;

  /// The mission's area as a Polygon feature (the datum as its `datum` property,
  /// [latitude, longitude], and every parameter that differs from its default as a
  /// property) and its start and goal as Point features with their `role`: what
  /// `coverage_tool export` writes and GeoJsonMissionReader reads back.
  std::string mission(const Mission& mission) const;

 private:
  std::string position(const Point2& local) const;
  std::string ring(const Ring& ring, bool counter_clockwise) const;

  LocalEastNorthFrame frame_;
};

}  // namespace kinematic_coverage::core
