#include "polygon_coverage_ros_bridge/mission/plan_command.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/mission/command_line.h"
#include "polygon_coverage_ros_bridge/mission/json_object.h"
#include "polygon_coverage_ros_bridge/mission/mission_planner.h"
#include "polygon_coverage_ros_bridge/mission/trajectory_coverage.h"
#include "polygon_coverage_ros_bridge/mission/waypoint_csv_writer.h"
#include "polygon_coverage_ros_bridge/validation/point_format.h"
#include "trajectory_generation_tools/plot/coverage_plot.h"
#include "trajectory_generation_tools/trajectory/trajectory_csv_writer.h"
#include "trajectory_generation_tools/trajectory/trajectory_generator.h"

namespace kinematic_coverage::core {

std::string PlanCommand::usage() {
  return "usage: coverage_tool plan MISSION.yaml --out DIR [--set name=value ...]\n"
         "  Plans a coverage path over the mission's polygon and writes DIR/waypoints.csv\n"
         "  (x,y,yaw), DIR/trajectory.csv (t,x,y,yaw,kind), DIR/metrics.json (with the\n"
         "  trajectory's coverage) and DIR/plot.png. --set overrides a parameter of "
         "config/default.yaml (the\n"
         "  value is read as YAML), after the mission file.\n";
}

void PlanCommand::run(const std::vector<std::string>& args, std::ostream& out,
                      std::ostream& err) const {
  const CommandArguments arguments = parseCommandArguments("plan", args, {{"--out", "DIR"}});
  if (arguments.help) {
    out << usage();
    return;
  }
  const std::string& out_dir = arguments.values.at("--out");
  // Progress goes to `out` as each stage finishes; warnings and notes go to `err` only
  // once the command has succeeded, so that a failure prints just its one error line.
  const Mission mission = loadMission(arguments, out);

  const PlannedMission planned = planMission(mission, [&](const PlanningStage& stage) {
    out << stage.name << ": " << stage.summary << " (" << formatSeconds(stage.duration_s) << ")"
        << std::endl;
  });
  const CoveragePlan& plan = planned.plan;
  const double planning_time_s = planned.planning_time_s;
  std::ostringstream notes;
  for (const std::string& warning : planned.warnings) notes << "warning: " << warning << "\n";

  const auto stage_start = std::chrono::steady_clock::now();
  const GeneratedTrajectory trajectory =
      TrajectoryGenerator(mission.parameters).generate(plan.waypoints, planned.free_area);
  const SmoothingStatistics& turns = trajectory.statistics;
  out << (mission.parameters.smoothing ? "smooth: " : "trajectory: ") << turns.turns_smoothed
      << " of " << turns.turns_total << " turns smoothed (inner " << turns.inner
      << ", outer bisector " << turns.outer_bisector << ", outer tangent " << turns.outer_tangent
      << "), " << trajectory.poses.size() << " poses, " << formatNumber(trajectory.traversal_time_s)
      << " s (" << formatSeconds(secondsSince(stage_start)) << ")" << std::endl;

  // Coverage of the poses as trajectory.csv holds them (yaw wrapped into (-pi, pi]), so
  // that `coverage_tool evaluate` of that file reports the same figures.
  std::vector<Pose2> poses;
  poses.reserve(trajectory.poses.size());
  for (const TrajectoryPose& pose : trajectory.poses) {
    poses.push_back({pose.x, pose.y, wrapAngle(pose.yaw)});
  }
  const TrajectoryCoverage coverage = measureTrajectoryCoverage(
      planned.free_area, plan.offset_free_area, mission.parameters, poses);
  out << "coverage: " << coverageSummary(coverage) << " (" << formatSeconds(coverage.duration_s)
      << ")" << std::endl;

  createOutputDirectory(out_dir);
  const std::filesystem::path dir(out_dir);
  const std::string waypoints_path = (dir / "waypoints.csv").string();
  const std::string trajectory_path = (dir / "trajectory.csv").string();
  const std::string metrics_path = (dir / "metrics.json").string();
  const std::string plot_path = (dir / "plot.png").string();
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
  setCoverageMetrics(coverage.report, metrics);
  if (std::isfinite(trajectory.min_obstacle_clearance_m)) {
    metrics.set("min_obstacle_clearance_m", trajectory.min_obstacle_clearance_m);
  }
  metrics.write(metrics_path);

  CoveragePlotData plot;
  plot.free_area = planned.free_area;
  plot.offset_free_area = plan.offset_free_area;
  plot.heatmap = coverage.heatmap;
  plot.waypoints = plan.waypoints;
  plot.trajectory = poses;
  plot.start = mission.start;
  plot.goal = mission.goal;
  std::ostringstream title;
  title << "Coverage plan: " << std::filesystem::path(arguments.mission_path).filename().string()
        << (mission.parameters.smoothing ? " (smoothed)" : " (unsmoothed)");
  std::ostringstream figures;
  figures.precision(4);
  figures << "coverage " << coverage.report.coverage_percent << " %  |  loss "
          << coverage.report.coverage_loss_percent << " %  |  " << turns.turns_smoothed << " of "
          << turns.turns_total << " turns smoothed  |  " << trajectory.trajectory_length_m
          << " m  |  " << trajectory.traversal_time_s << " s";
  plot.title_lines = {title.str(), figures.str()};
  CoveragePlot().writePng(plot, plot_path);
  err << notes.str();
  out << "write: " << plan.waypoints.size() << " waypoints, planning took "
      << formatSeconds(planning_time_s) << "\n";
  out << "wrote " << waypoints_path << " " << trajectory_path << " " << metrics_path << " "
      << plot_path << "\n";
}

}  // namespace kinematic_coverage::core
