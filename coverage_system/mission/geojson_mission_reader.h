#pragma once

#include <optional>
#include <string>
#include <vector>

#include "coverage_system/mission/mission.h"

namespace kinematic_coverage::core {

/// Reads geo-referenced missions (docs/REFERENCE.md, File formats): a
/// GeoJSON FeatureCollection in WGS84 ([longitude, latitude]) with one Polygon feature (its
/// first ring the hull, the others holes; a MultiPolygon or several Polygon features are
/// unioned, holes kept, and must make one area) and Point features with the property
/// "role": "start" and "role": "goal". The polygon feature's properties are parameters as
/// in a mission file, but for `datum` ([latitude, longitude], the origin of the local
/// east-north frame; default: the centre of the hull's extent in latitude and longitude)
/// and `frame_id` (default "map").
/// The mission comes out in the plane its `projection` parameter names (MissionFrame: the
/// local east-north frame or the datum's UTM zone), in metres, with its datum.
/// Every problem is an InvalidInputError naming the file and what is wrong: not JSON, not
/// a FeatureCollection, no Polygon, a missing or repeated start or goal, coordinates outside
/// [-180, 180] x [-90, 90], a point the projection does not reach (with the area's
/// extent), an unknown parameter or one out of range.
class GeoJsonMissionReader {
 public:
  /// `datum`, when given, anchors the local frame instead of the file's `datum` (or its
  /// hull's centre): missions from several charts then share one frame, e.g. a
  /// robot's map whose origin is known (mission_publisher's `~datum`).
  explicit GeoJsonMissionReader(std::optional<GeoPoint> datum = std::nullopt);

  /// True when `path` names a GeoJSON file (extension .geojson or .json, any case).
  static bool isGeoJsonPath(const std::string& path);

  /// Reads the file at `path` over the parameters `base`, then applies `overrides`
  /// ("name=value" each), as MissionFileReader::read does.
  Mission read(const std::string& path, const std::vector<std::string>& overrides = {},
               const PlannerParameters& base = PlannerParameters{}) const;

  /// As read(), from the file's text; `source_name` names it in messages.
  Mission parse(const std::string& text, const std::string& source_name,
                const std::vector<std::string>& overrides = {},
                const PlannerParameters& base = PlannerParameters{}) const;

 private:
  std::optional<GeoPoint> datum_;
};

}  // namespace kinematic_coverage::core
