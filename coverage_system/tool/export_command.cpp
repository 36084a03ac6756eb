#include "coverage_system/tool/export_command.h"

#include <filesystem>
#include <optional>

#include "coverage_system/mission/mission_frame.h"
#include "coverage_system/tool/command_line.h"
#include "coverage_system/tool/geojson_writer.h"
#include "polygon_coverage_ros_bridge/base/text_file_writer.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {
std::string ExportCommand::usage() {
  return "usage: coverage_tool export MISSION.yaml --datum LAT,LON --out FILE.geojson\n"
         "                           [--config FILE] [--set name=value ...]\n"
         "  Writes the mission's area, start and goal as a GeoJSON FeatureCollection in\n"
         "  WGS84, its coordinates taken as metres east and north of the datum, the datum\n"
         "  and every parameter that differs from its default as properties of the polygon\n"
         "  feature. `coverage_tool plan FILE.geojson` plans it.\n";
}

void ExportCommand::run(const std::vector<std::string>& args, std::ostream& out,
                        std::ostream&) const {
  std::optional<MissionCommandInput> input = startMissionCommand(
      "export", args, {{"--datum", "LAT,LON"}, {"--out", "FILE.geojson"}}, usage(), out);
  if (!input) return;
  const CommandArguments& arguments = input->arguments;
  const GeoPoint datum = parseDatum(arguments.values.at("--datum"));
  Mission& mission = input->mission;
  const MissionFrame frame = MissionFrame::of(datum, mission.parameters);
  // Every point within the projection's reach, as the reader will ask.
  auto check = [&](const Point2& p, const std::string& what) {
    frame.toLocal(frame.toGeographic(p), what);
  };
  for (const Point2& p : mission.polygon.hull) check(p, "a hull vertex");
  for (const Ring& hole : mission.polygon.holes) {
    for (const Point2& p : hole) check(p, "a hole vertex");
  }
  mission.datum = datum;
  const std::string& path = arguments.values.at("--out");
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) createOutputDirectory(parent.string());
  writeTextFile(path, GeoJsonWriter(frame).mission(mission));
  out << "wrote " << path << "\n";
}

}  // namespace kinematic_coverage::core
