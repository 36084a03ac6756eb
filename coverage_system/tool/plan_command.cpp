#include "coverage_system/tool/plan_command.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>

#include "coverage_system/mission/mission_planner.h"
#include "coverage_system/mission/trajectory_coverage.h"
#include "coverage_system/tool/command_line.h"
#include "coverage_system/tool/json_object.h"
#include "coverage_system/tool/plan_output_writer.h"
#include "coverage_system/tool/trajectory_csv_writer.h"
#include "coverage_system/tool/waypoint_csv_writer.h"
#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "trajectory_generation_tools/plot/coverage_plot.h"
#include "trajectory_generation_tools/trajectory/trajectory_generator.h"

namespace kinematic_coverage::core {

std::string PlanCommand::usage() {
  return "usage: coverage_tool plan MISSION.yaml --out DIR [--config FILE]\n"
         "                         [--set name=value ...] [--datum LAT,LON]\n"
         "  Plans a coverage path over the mission's polygon and writes DIR/waypoints.csv\n"
         "  (x,y,yaw), DIR/trajectory.csv (t,x,y,yaw,kind), DIR/metrics.json (with the\n"
         "  trajectory's coverage) and DIR/plot.png; for a GeoJSON mission (MISSION.geojson)\n"
         "  also DIR/waypoints.geojson, DIR/trajectory.geojson and the vehicle's mission\n"
         "  files DIR/mission.plan (QGroundControl) and DIR/mission.waypoints (QGC WPL 110).\n"
         "  --datum LAT,LON places a mission in metres (MISSION.yaml) there, its x east and y\n"
         "  north of the datum, and writes those files too.\n"
         "  --set overrides a parameter of\n"
         "  config/default.yaml (the value is read as YAML), after the mission file.\n"
         "  --config FILE reads the parameters of FILE (as config/default.yaml, e.g.\n"
         "  config/thesis.yaml) over the built-in defaults, before the mission file.\n";
}

void PlanCommand::run(const std::vector<std::string>& args, std::ostream& out,
                      std::ostream& err) const {
  // Progress goes to `out` as each stage finishes; warnings and notes go to `err` only
  // once the command has succeeded, so that a failure prints just its one error line.
  std::optional<MissionCommandInput> input = startMissionCommand(
      "plan", args, {{"--out", "DIR"}, {"--datum", "LAT,LON", false}}, usage(), out);
  if (!input) return;
  const std::string& out_dir = input->arguments.values.at("--out");
  Mission& mission = input->mission;
  if (const auto datum = input->arguments.values.find("--datum");
      datum != input->arguments.values.end()) {
    if (mission.datum) {
      throw InvalidInputError("--datum " + datum->second + ": " + input->arguments.mission_path +
                              " is geo-referenced already (its datum is " +
                              formatNumber(mission.datum->latitude) + "," +
                              formatNumber(mission.datum->longitude) + ")");
    }
    mission.datum = parseDatum(datum->second);
  }

  const PlannedMission planned = planMission(mission, [&](const PlanningStage& stage) {
    out << stage.name << ": " << stage.summary << " (" << formatSeconds(stage.duration_s) << ")"
        << std::endl;
  });
  const CoveragePlan& plan = planned.plan;
  const double planning_time_s = planned.planning_time_s;
  std::ostringstream notes;
  for (const std::string& warning : planned.warnings) notes << "warning: " << warning << "\n";

  PlanOutputRequest request;
  request.parameters = &mission.parameters;
  request.free_area = &planned.free_area;
  request.plan = &plan;
  request.planning_time_s = planning_time_s;
  request.start = mission.start;
  request.goal = mission.goal;
  request.frame_id = mission.frame_id;
  if (mission.datum) request.frame = MissionFrame::of(*mission.datum, mission.parameters);
  request.title =
      "Coverage plan: " + std::filesystem::path(input->arguments.mission_path).filename().string() +
      (mission.parameters.smoothing ? " (smoothed)" : " (unsmoothed)");
  const PlanOutputs outputs = writePlanOutputs(request, out_dir, out);
  for (const std::string& warning : outputs.warnings) notes << "warning: " << warning << "\n";
  err << notes.str();
  out << "write: " << plan.waypoints.size() << " waypoints, planning took "
      << formatSeconds(planning_time_s) << "\n";
  out << "wrote";
  for (const std::string& path : outputs.files) out << " " << path;
  out << "\n";
}

}  // namespace kinematic_coverage::core
