#pragma once

#include <string>

#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "test/support/hard_map_generator.h"

namespace kinematic_coverage::core {
namespace testing {

/// `[[x, y], ...]`, every number in the shortest text that reads back exactly.
inline std::string ringYaml(const Ring& ring) {
  std::string text = "[";
  for (std::size_t i = 0; i < ring.size(); ++i) {
    text += (i ? ", [" : "[") + formatRoundTrip(ring[i].x()) + ", " + formatRoundTrip(ring[i].y()) +
            "]";
  }
  return text + "]";
}

/// The mission as a mission file that `coverage_tool plan` reads (docs/REFERENCE.md, File
/// formats): `comment` as its first line, the polygon, start, goal and the parameters the
/// map generators vary; MissionFileReader reads it back to the same mission.
inline std::string missionYaml(const Mission& m, const std::string& comment) {
  const PlannerParameters& p = m.parameters;
  const auto point = [](const Point2& q) {
    return "[" + formatRoundTrip(q.x()) + ", " + formatRoundTrip(q.y()) + "]";
  };
  std::string text = "# " + comment + "\n";
  text +=
      "frame_id: " + m.frame_id + "\npolygon:\n  hull: " + ringYaml(m.polygon.hull) + "\n  holes:";
  if (m.polygon.holes.empty()) text += " []";
  for (const Ring& hole : m.polygon.holes) text += "\n    - " + ringYaml(hole);
  text += "\nstart: " + point(m.start) + "\ngoal: " + point(m.goal) + "\n";
  text += "decomposition_type: " + p.decomposition_type + "\n";
  text += "wall_distance: " + formatRoundTrip(p.wall_distance) + "\n";
  if (p.gap_clearance != kClearanceOfWallDistance) {
    text += "gap_clearance: " + formatRoundTrip(p.gap_clearance) + "\n";
  }
  text += "sensor_distance: " + formatRoundTrip(p.sensor_distance) + "\n";
  text += "lateral_fov: " + formatRoundTrip(p.lateral_fov) + "\n";
  text += "onward_fov: " + formatRoundTrip(p.onward_fov) + "\n";
  text += "lateral_overlap: " + formatRoundTrip(p.lateral_overlap) + "\n";
  text += "turning_radius: " + formatRoundTrip(p.turning_radius) + "\n";
  return text;
}

/// The map as a mission file (missionYaml), its comment naming family, seed and footprint.
inline std::string hardMapYaml(const HardMap& map) {
  return missionYaml(map.mission, "HardMapGenerator family " + HardMapGenerator::name(map.family) +
                                      ", seed " + std::to_string(map.seed) + ": footprint " +
                                      formatRoundTrip(map.footprint_width_m) + " m x " +
                                      formatRoundTrip(map.footprint_length_m) + " m");
}

}  // namespace testing
}  // namespace kinematic_coverage::core
