#include "coverage_system/tool/replan_command.h"

#include <filesystem>
#include <optional>
#include <sstream>

#include "coverage_system/mission/mission_file_reader.h"
#include "coverage_system/mission/pose_csv_reader.h"
#include "coverage_system/planner/replanner.h"
#include "coverage_system/tool/command_line.h"
#include "coverage_system/tool/plan_output_writer.h"
#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/base/text_file_writer.h"

namespace kinematic_coverage::core {
namespace {

std::string ringYaml(const Ring& ring) {
  std::string text = "[";
  for (std::size_t i = 0; i < ring.size(); ++i) {
    text += (i ? ", [" : "[") + formatRoundTrip(ring[i].x()) + ", " + formatRoundTrip(ring[i].y()) +
            "]";
  }
  return text + "]";
}

/// The remaining parts as a YAML list of `{hull, holes}` maps.
std::string remainingYaml(const std::vector<PolygonWithHoles>& parts) {
  if (parts.empty()) return "[]\n";
  std::string text;
  for (const PolygonWithHoles& part : parts) {
    text += "- hull: " + ringYaml(part.hull) + "\n  holes: [";
    for (std::size_t i = 0; i < part.holes.size(); ++i) {
      text += (i ? ", " : "") + ringYaml(part.holes[i]);
    }
    text += "]\n";
  }
  return text;
}

}  // namespace

std::string ReplanCommand::usage() {
  return "usage: coverage_tool replan MISSION.yaml --updated UPDATED.yaml --visited FILE.csv\n"
         "                           --out DIR [--config FILE] [--set name=value ...]\n"
         "  Replans after obstacles moved: the area the visited poses (CSV with columns x, y,\n"
         "  yaw) have not seen, in the updated polygon (UPDATED.yaml holds a `polygon:`), by\n"
         "  replanning_method, planned from the last visited pose to the mission's goal.\n"
         "  Writes the files of `plan` and DIR/remaining.yaml. --set overrides a parameter\n"
         "  of config/default.yaml (the value is read as YAML), after the mission file.\n"
         "  --config FILE reads the parameters of FILE (as config/default.yaml, e.g.\n"
         "  config/thesis.yaml) over the built-in defaults, before the mission file.\n";
}

void ReplanCommand::run(const std::vector<std::string>& args, std::ostream& out,
                        std::ostream& err) const {
  const std::optional<MissionCommandInput> input = startMissionCommand(
      "replan", args, {{"--updated", "UPDATED.yaml"}, {"--visited", "FILE.csv"}, {"--out", "DIR"}},
      usage(), out);
  if (!input) return;
  const CommandArguments& arguments = input->arguments;
  const Mission& mission = input->mission;
  const PolygonWithHoles updated =
      MissionFileReader().readUpdatedPolygon(arguments.values.at("--updated"));
  const std::vector<Pose2> visited = PoseCsvReader().readPoses(arguments.values.at("--visited"));
  out << "read: " << updated.holes.size() << " updated holes, " << visited.size()
      << " visited poses" << std::endl;

  const ReplannedMission replanned =
      Replanner(mission.parameters)
          .replan(updated, visited, mission.goal, [&](const PlanningStage& stage) {
            out << stage.name << ": " << stage.summary << " (" << formatSeconds(stage.duration_s)
                << ")" << std::endl;
          });
  PlanOutputRequest request;
  request.parameters = &mission.parameters;
  request.free_area = &replanned.free_area;
  request.plan = &replanned.plan;
  request.planning_time_s = replanned.planning_time_s;
  request.start = replanned.start;
  request.goal = mission.goal;
  request.title = "Replan: " + std::filesystem::path(arguments.mission_path).filename().string() +
                  " (" + mission.parameters.replanning_method + ")";
  request.visited = visited;
  const PlanOutputs outputs = writePlanOutputs(request, arguments.values.at("--out"), out);
  std::vector<std::string> written = outputs.files;
  const std::string remaining_path =
      (std::filesystem::path(arguments.values.at("--out")) / "remaining.yaml").string();
  writeTextFile(remaining_path, remainingYaml(replanned.remaining.parts));
  written.push_back(remaining_path);

  std::ostringstream notes;
  for (const std::string& warning : replanned.warnings) notes << "warning: " << warning << "\n";
  for (const std::string& warning : outputs.warnings) notes << "warning: " << warning << "\n";
  err << notes.str();
  out << "write: " << replanned.plan.waypoints.size() << " waypoints, replanning took "
      << formatSeconds(replanned.planning_time_s) << "\n";
  out << "wrote";
  for (const std::string& path : written) out << " " << path;
  out << "\n";
}

}  // namespace kinematic_coverage::core
