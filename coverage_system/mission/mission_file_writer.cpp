#include "coverage_system/mission/mission_file_writer.h"

#include <string>

#include "coverage_system/mission/mission_file_reader.h"
#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/base/text_file_writer.h"

namespace kinematic_coverage::core {
namespace {

std::string pointText(const Point2& p) {
  return "[" + formatRoundTrip(p.x()) + ", " + formatRoundTrip(p.y()) + "]";
}

/// A YAML single-quoted scalar: quotes doubled.
std::string quoted(const std::string& value) {
  std::string text = "'";
  for (char c : value) text += c == '\'' ? std::string("''") : std::string(1, c);
  return text + "'";
}

std::string ringText(const Ring& ring) {
  std::string text = "[";
  for (std::size_t i = 0; i < ring.size(); ++i) text += (i ? ", " : "") + pointText(ring[i]);
  return text + "]";
}

}  // namespace

std::string MissionFileWriter::text(const Mission& mission, const std::string& comment) {
  std::string text;
  if (!comment.empty()) text += "# " + comment + "\n";
  text += "frame_id: " + quoted(mission.frame_id) + "\n";
  text += "polygon:\n  hull: " + ringText(mission.polygon.hull) + "\n  holes:";
  if (mission.polygon.holes.empty()) text += " []";
  for (const Ring& hole : mission.polygon.holes) text += "\n    - " + ringText(hole);
  text += "\nstart: " + pointText(mission.start) + "\ngoal: " + pointText(mission.goal) + "\n";
  const PlannerParameters defaults;
  for (const std::string& name : MissionFileReader::parameterNames()) {
    const std::string value = MissionFileReader::parameterText(mission.parameters, name);
    if (value != MissionFileReader::parameterText(defaults, name)) {
      text += name + ": " + value + "\n";
    }
  }
  return text;
}

void MissionFileWriter::write(const Mission& mission, const std::string& path,
                              const std::string& comment) {
  writeTextFile(path, text(mission, comment));
}

}  // namespace kinematic_coverage::core
