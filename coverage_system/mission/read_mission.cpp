#include "coverage_system/mission/read_mission.h"

#include "coverage_system/mission/geojson_mission_reader.h"
#include "coverage_system/mission/mission_file_reader.h"

namespace kinematic_coverage::core {

Mission readMission(const std::string& path, const std::vector<std::string>& overrides,
                    const PlannerParameters& base, const std::optional<GeoPoint>& datum) {
  if (GeoJsonMissionReader::isGeoJsonPath(path)) {
    return GeoJsonMissionReader(datum).read(path, overrides, base);
  }
  return MissionFileReader().read(path, overrides, base);
}

}  // namespace kinematic_coverage::core
