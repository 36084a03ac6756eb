#include "polygon_coverage_ros_bridge/mission/plan_command.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/mission/json_object.h"
#include "polygon_coverage_ros_bridge/mission/mission_file_reader.h"
#include "polygon_coverage_ros_bridge/mission/mission_planner.h"
#include "polygon_coverage_ros_bridge/mission/waypoint_csv_writer.h"
#include "polygon_coverage_ros_bridge/validation/point_format.h"
#include "trajectory_generation_tools/trajectory/trajectory_csv_writer.h"
#include "trajectory_generation_tools/trajectory/trajectory_generator.h"

namespace kinematic_coverage {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string seconds(double value) {
  std::ostringstream out;
  out.precision(3);
  out << std::fixed << value << " s";
  return out.str();
}

struct PlanArguments {
  std::string mission_path;
  std::string out_dir;
  std::vector<std::string> overrides;
  bool help = false;
};

PlanArguments parseArguments(const std::vector<std::string>& args) {
  PlanArguments parsed;
  bool has_out = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) {
        throw InvalidInputError("coverage_tool plan: " + arg + " needs a value");
      }
      return args[++i];
    };
    if (arg == "--help" || arg == "-h") {
      parsed.help = true;
    } else if (arg == "--out") {
      parsed.out_dir = value();
      has_out = true;
    } else if (arg == "--set") {
      parsed.overrides.push_back(value());
    } else if (arg.size() > 1 && arg[0] == '-') {
      throw InvalidInputError("coverage_tool plan: unknown option '" + arg +
                              "' (see coverage_tool plan --help)");
    } else if (parsed.mission_path.empty()) {
      parsed.mission_path = arg;
    } else {
      throw InvalidInputError("coverage_tool plan: one mission file expected, got '" +
                              parsed.mission_path + "' and '" + arg + "'");
    }
  }
  if (parsed.help) return parsed;
  if (parsed.mission_path.empty()) {
    throw InvalidInputError(
        "coverage_tool plan: no mission file given (see coverage_tool plan --help)");
  }
  if (!has_out || parsed.out_dir.empty()) {
    throw InvalidInputError("coverage_tool plan: --out DIR is required");
  }
  return parsed;
}

void createDirectory(const std::string& dir) {
  std::error_code code;
  std::filesystem::create_directories(dir, code);
  if (code || !std::filesystem::is_directory(dir)) {
    throw InvalidInputError("cannot create the output directory " + dir +
                            (code ? ": " + code.message() : ""));
  }
}

}  // namespace

std::string PlanCommand::usage() {
  return "usage: coverage_tool plan MISSION.yaml --out DIR [--set name=value ...]\n"
         "  Plans a coverage path over the mission's polygon and writes DIR/waypoints.csv\n"
         "  (x,y,yaw) and DIR/metrics.json. --set overrides a parameter of\n"
         "  config/default.yaml (the value is read as YAML), after the mission file.\n";
}

void PlanCommand::run(const std::vector<std::string>& args, std::ostream& out,
                      std::ostream& err) const {
  const PlanArguments arguments = parseArguments(args);
  if (arguments.help) {
    out << usage();
    return;
  }
  // Progress goes to `out` as each stage finishes; warnings and notes go to `err` only
  // once the command has succeeded, so that a failure prints just its one error line.
  Clock::time_point stage_start = Clock::now();
  const Mission mission = MissionFileReader().read(arguments.mission_path, arguments.overrides);
  out << "load: " << arguments.mission_path << ": hull of " << mission.polygon.hull.size()
      << " vertices, " << mission.polygon.holes.size() << " holes, frame " << mission.frame_id
      << " (" << seconds(secondsSince(stage_start)) << ")" << std::endl;

  const PlannedMission planned = planMission(mission, [&](const PlanningStage& stage) {
    out << stage.name << ": " << stage.summary << " (" << seconds(stage.duration_s) << ")"
        << std::endl;
  });
  const CoveragePlan& plan = planned.plan;
  const double planning_time_s = planned.planning_time_s;
  std::ostringstream notes;
  for (const std::string& warning : planned.warnings) notes << "warning: " << warning << "\n";

  stage_start = Clock::now();
  const GeneratedTrajectory trajectory =
      TrajectoryGenerator(mission.parameters).generate(plan.waypoints, planned.free_area);
  const SmoothingStatistics& turns = trajectory.statistics;
  out << (mission.parameters.smoothing ? "smooth: " : "trajectory: ") << turns.turns_smoothed
      << " of " << turns.turns_total << " turns smoothed (inner " << turns.inner
      << ", outer bisector " << turns.outer_bisector << ", outer tangent " << turns.outer_tangent
      << "), " << trajectory.poses.size() << " poses, " << formatNumber(trajectory.traversal_time_s)
      << " s (" << seconds(secondsSince(stage_start)) << ")" << std::endl;

  createDirectory(arguments.out_dir);
  const std::filesystem::path dir(arguments.out_dir);
  const std::string waypoints_path = (dir / "waypoints.csv").string();
  const std::string trajectory_path = (dir / "trajectory.csv").string();
  const std::string metrics_path = (dir / "metrics.json").string();
  WaypointCsvWriter().write(waypoints_path, plan.waypoints);
  TrajectoryCsvWriter().write(trajectory_path, trajectory.poses);
  JsonObject metrics;
  metrics.set("planning_time_s", planning_time_s)
      .set("cells", static_cast<double>(plan.cells.size()))
      .set("waypoint_count", static_cast<double>(plan.waypoints.size()))
      .set("path_length_m", plan.path_length_m)
      .set("time_cost_s", plan.time_cost_s)
      .set("trajectory_length_m", trajectory.trajectory_length_m)
      .set("traversal_time_s", trajectory.traversal_time_s)
      .set("max_curvature", trajectory.max_curvature)
      .set("turns_total", static_cast<double>(turns.turns_total))
      .set("turns_smoothed", static_cast<double>(turns.turns_smoothed));
  if (std::isfinite(trajectory.min_obstacle_clearance_m)) {
    metrics.set("min_obstacle_clearance_m", trajectory.min_obstacle_clearance_m);
  }
  metrics.write(metrics_path);
  notes << "note: plot.png and the coverage metrics are not produced yet (they arrive with "
           "issue 5)\n";
  err << notes.str();
  out << "write: " << plan.waypoints.size() << " waypoints, planning took "
      << seconds(planning_time_s) << "\n";
  out << "wrote " << waypoints_path << " " << trajectory_path << " " << metrics_path << "\n";
}

}  // namespace kinematic_coverage
