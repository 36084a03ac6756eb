#include "coverage_system/tool/plan_output_writer.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>

#include "coverage_system/mission/autopilot_mission.h"
#include "coverage_system/mission/mission_frame.h"
#include "coverage_system/mission/trajectory_coverage.h"
#include "coverage_system/mission/trajectory_pipeline.h"
#include "coverage_system/mission/wall_clearance_warning.h"
#include "coverage_system/parameters/stage_options.h"
#include "coverage_system/tool/autopilot_mission_writer.h"
#include "coverage_system/tool/command_line.h"
#include "coverage_system/tool/coverage_metrics.h"
#include "coverage_system/tool/geojson_writer.h"
#include "coverage_system/tool/json_object.h"
#include "coverage_system/tool/trajectory_csv_writer.h"
#include "coverage_system/tool/waypoint_csv_writer.h"
#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/base/text_file_writer.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/route/segment_cost.h"
#include "trajectory_generation_tools/plot/coverage_plot.h"
#include "trajectory_generation_tools/trajectory/trajectory_thinning.h"

namespace kinematic_coverage::core {

namespace {

/// The progress line of the trajectory stage.
void writeTrajectoryLine(const PlannerParameters& parameters, const MeasuredTrajectory& measured,
                         std::ostream& out) {
  const GeneratedTrajectory& trajectory = measured.trajectory;
  const SmoothingStatistics& turns = trajectory.statistics;
  out << (parameters.smoothing ? "smooth: " : "trajectory: ") << turns.turns_smoothed << " of "
      << turns.turns_total << " turns smoothed (inner " << turns.inner << ", outer bisector "
      << turns.outer_bisector << ", outer tangent " << turns.outer_tangent << ", reverse curve "
      << turns.reverse_curve << ", bulb " << turns.bulb << "; kept sharp for coverage "
      << turns.kept_for_coverage << "), " << trajectory.poses.size() << " poses, "
      << formatNumber(trajectory.traversal_time_s) << " s (" << formatSeconds(measured.generation_s)
      << ")" << std::endl;
}

/// metrics.json (docs/REFERENCE.md, Metrics).
JsonObject planMetrics(const PlanOutputRequest& request, const GeneratedTrajectory& trajectory,
                       const TrajectoryCoverage& coverage,
                       const std::optional<TrajectoryCoverage>& combined) {
  const CoveragePlan& plan = *request.plan;
  const SmoothingStatistics& turns = trajectory.statistics;
  JsonObject metrics;
  metrics.set("planning_time_s", request.planning_time_s)
      .set("cells", static_cast<double>(plan.cells.size()))
      .set("waypoint_count", static_cast<double>(plan.waypoints.size()))
      .set("path_length_m", plan.path_length_m)
      .set("time_cost_s", plan.time_cost_s)
      .set("trajectory_length_m", trajectory.trajectory_length_m)
      .set("traversal_time_s", trajectory.traversal_time_s)
      .set("max_curvature", trajectory.max_curvature)
      .set("turns_total", static_cast<double>(turns.turns_total))
      .set("turns_smoothed", static_cast<double>(turns.turns_smoothed))
      .set("turns_inner", static_cast<double>(turns.inner))
      .set("turns_outer_bisector", static_cast<double>(turns.outer_bisector))
      .set("turns_outer_tangent", static_cast<double>(turns.outer_tangent))
      .set("turns_reverse_curve", static_cast<double>(turns.reverse_curve))
      .set("turns_bulb", static_cast<double>(turns.bulb))
      .set("turns_clothoid", static_cast<double>(turns.clothoid))
      .set("turns_sharp", static_cast<double>(turns.turns_total - turns.turns_smoothed))
      .setJson("gtsp_time_capped", plan.gtsp_time_capped ? "true" : "false");
  setCoverageMetrics(coverage.report, metrics);
  if (combined) metrics.set("combined_coverage_percent", combined->report.coverage_percent);
  // Replanning: what the visited poses and the new trajectory fail to see together.
  const TrajectoryCoverage& searched = combined ? *combined : coverage;
  if (const std::optional<LostArea>& lost = searched.lost_to_reference) {
    metrics.set("smoothing_lost_area_m2", lost->area_m2)
        .set("smoothing_lost_reachable_area_m2", lost->reachable_area_m2);
  }
  if (std::isfinite(trajectory.min_obstacle_clearance_m)) {
    metrics.set("min_obstacle_clearance_m", trajectory.min_obstacle_clearance_m);
  }
  if (request.frame) {
    metrics.set("frame_id", request.frame_id);
    GeoJsonWriter::setFrame(*request.frame, metrics);
  }
  return metrics;
}

/// DIR/waypoints.geojson and DIR/trajectory.geojson of a geo-referenced plan; their paths.
std::vector<std::string> writeGeoJson(const PlanOutputRequest& request,
                                      const std::vector<TrajectoryPose>& written_poses,
                                      const std::filesystem::path& dir) {
  const GeoJsonWriter writer{*request.frame};
  const SegmentCost time_cost(CostFunction::kTime, vehicleLimitsOf(*request.parameters));
  std::vector<Point2> waypoints;
  std::vector<double> waypoint_times;
  for (const Pose2& waypoint : request.plan->waypoints) {
    waypoint_times.push_back(waypoints.empty()
                                 ? 0.0
                                 : waypoint_times.back() +
                                       time_cost.of(waypoints.back(), waypoint.position()));
    waypoints.push_back(waypoint.position());
  }
  std::vector<Point2> poses;
  std::vector<double> pose_times;
  for (const TrajectoryPose& pose : written_poses) {
    poses.emplace_back(pose.x, pose.y);
    pose_times.push_back(pose.t);
  }
  const std::string waypoints_path = (dir / "waypoints.geojson").string();
  const std::string trajectory_path = (dir / "trajectory.geojson").string();
  writeTextFile(waypoints_path,
                writer.lineString(waypoints, waypoint_times, "waypoints", request.frame_id));
  writeTextFile(trajectory_path,
                writer.lineString(poses, pose_times, "trajectory", request.frame_id));
  return {waypoints_path, trajectory_path};
}

/// DIR/mission.plan and DIR/mission.waypoints of a geo-referenced plan (the vehicle's
/// mission files), with their progress line; warnings go to `warnings`, the written paths to
/// `files`.
void writeAutopilotMission(const PlanOutputRequest& request, const GeneratedTrajectory& trajectory,
                           const std::filesystem::path& dir, std::ostream& out,
                           std::vector<std::string>* files, std::vector<std::string>* warnings) {
  const PlannerParameters& p = *request.parameters;
  const AutopilotMission mission =
      AutopilotMissionBuilder(vehicleLimitsOf(p), p.corner_cutting_radius)
          .build(trajectory.path, *request.free_area, p.wall_distance);
  const AutopilotMissionWriter writer(*request.frame, {p.mission_depth, p.corner_cutting_radius},
                                      mission);
  const std::size_t items = writer.itemCount();
  const std::string plan_path = (dir / "mission.plan").string();
  const std::string waypoints_path = (dir / "mission.waypoints").string();
  writeTextFile(plan_path, writer.planJson());
  writeTextFile(waypoints_path, writer.waypointsText());
  files->push_back(plan_path);
  files->push_back(waypoints_path);
  const std::size_t held = static_cast<std::size_t>(
      std::count_if(mission.waypoints.begin(), mission.waypoints.end(),
                    [](const AutopilotWaypoint& waypoint) { return waypoint.hold; }));
  out << "mission: " << mission.waypoints.size() << " waypoints (" << held << " held), " << items
      << " items, for an autopilot that cuts each waypoint by "
      << formatNumber(p.corner_cutting_radius) << " m (ArduSub: set WPNAV_RADIUS to "
      << formatNumber(100.0 * p.corner_cutting_radius) << " cm); the cut path comes "
      << formatNumber(mission.corner_cut_clearance_m) << " m from the walls" << std::endl;
  const double kept = std::min(p.wall_distance, trajectory.min_obstacle_clearance_m);
  if (mission.corner_cut_clearance_m < kept - kClearanceTolerance) {
    warnings->push_back("the mission files' waypoint path comes " +
                        formatNumber(mission.corner_cut_clearance_m) + " m from the walls near " +
                        formatPoint(mission.closest_cut) + ", nearer than the trajectory's " +
                        formatNumber(kept) + " m");
  }
  if (items > AutopilotMissionWriter::kArduPilotItemLimit) {
    warnings->push_back("the mission files hold " + std::to_string(items) +
                        " items, more than the about " +
                        std::to_string(AutopilotMissionWriter::kArduPilotItemLimit) +
                        " an ArduPilot board keeps without an SD card for missions");
  }
  if (p.mission_depth == 0.0) {
    warnings->push_back(
        "the mission files send the vehicle to depth 0, the surface: set mission_depth to the "
        "survey's depth");
  }
}

/// plot.png's content: the areas, the heatmap (with the visited poses when replanning),
/// the paths and the title with the figures shown.
CoveragePlotData planPlot(const PlanOutputRequest& request, const std::vector<Pose2>& poses,
                          const GeneratedTrajectory& trajectory, const TrajectoryCoverage& coverage,
                          const std::optional<TrajectoryCoverage>& combined) {
  const SmoothingStatistics& turns = trajectory.statistics;
  CoveragePlotData plot;
  plot.free_area = *request.free_area;
  plot.offset_parts = request.plan->offset_parts;
  plot.unreachable_parts = request.plan->unreachable_parts;
  plot.heatmap = combined ? combined->heatmap : coverage.heatmap;
  plot.waypoints = request.plan->waypoints;
  plot.trajectory = poses;
  plot.start = request.start;
  plot.goal = request.goal;
  std::ostringstream figures;
  figures.precision(4);
  const CoverageReport& shown = combined ? combined->report : coverage.report;
  figures << (combined ? "coverage with visited " : "coverage ") << shown.coverage_percent
          << " %  |  loss " << shown.coverage_loss_percent << " %  |  " << turns.turns_smoothed
          << " of " << turns.turns_total << " turns smoothed  |  "
          << formatLength(trajectory.trajectory_length_m) << "  |  "
          << formatDuration(trajectory.traversal_time_s);
  plot.title_lines = {request.title, figures.str()};
  if (request.frame) {
    // True north at the middle of the drawn area, for the plot's north arrow.
    Point2 low = request.free_area->hull.front(), high = low;
    for (const Point2& p : request.free_area->hull) {
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
    plot.north_direction = request.frame->northDirection(0.5 * (low + high));
  }
  if (!keepsClearance(trajectory.min_obstacle_clearance_m, request.parameters->wall_distance)) {
    plot.closest_approach = trajectory.closest_approach;
  }
  return plot;
}

}  // namespace

PlanOutputs writePlanOutputs(const PlanOutputRequest& request, const std::string& out_dir,
                             std::ostream& out) {
  const TrajectoryPipeline pipeline(*request.parameters, request.plan->exact_offset_parts);
  // Replanning measures the new trajectory alone, and against its sharp path together with
  // the visited poses.
  const MeasuredTrajectory measured =
      pipeline.run(request.plan->waypoints, *request.free_area, !request.visited);
  writeTrajectoryLine(*request.parameters, measured, out);
  const GeneratedTrajectory& trajectory = measured.trajectory;
  const std::vector<Pose2>& poses = measured.poses;
  const TrajectoryCoverage& coverage = measured.coverage;
  out << "coverage: " << coverageSummary(coverage) << " (" << formatSeconds(coverage.duration_s)
      << ")" << std::endl;
  std::optional<TrajectoryCoverage> combined;
  if (request.visited) {
    std::vector<Pose2> all = *request.visited;
    all.insert(all.end(), poses.begin(), poses.end());
    std::optional<std::vector<Pose2>> all_unsmoothed;
    if (measured.sharp_poses) {
      all_unsmoothed = *request.visited;
      all_unsmoothed->insert(all_unsmoothed->end(), measured.sharp_poses->begin(),
                             measured.sharp_poses->end());
    }
    combined = pipeline.measure(*request.free_area, all, all_unsmoothed);
    out << "combined coverage: visited and new trajectory: " << coverageSummary(*combined) << " ("
        << formatSeconds(combined->duration_s) << ")" << std::endl;
  }

  createOutputDirectory(out_dir);
  const std::filesystem::path dir(out_dir);
  const std::string waypoints_path = (dir / "waypoints.csv").string();
  const std::string trajectory_path = (dir / "trajectory.csv").string();
  const std::string metrics_path = (dir / "metrics.json").string();
  const std::string plot_path = (dir / "plot.png").string();
  WaypointCsvWriter().write(waypoints_path, request.plan->waypoints);
  const std::vector<TrajectoryPose> written_poses =
      TrajectoryThinning(request.parameters->trajectory_output_spacing).apply(trajectory.poses);
  if (written_poses.size() < trajectory.poses.size()) {
    out << "thin: the trajectory files hold " << written_poses.size() << " of "
        << trajectory.poses.size() << " poses (one per "
        << formatNumber(request.parameters->trajectory_output_spacing)
        << " m, every primitive's ends and every curve's turns)" << std::endl;
  }
  TrajectoryCsvWriter().write(trajectory_path, written_poses);
  planMetrics(request, trajectory, coverage, combined).write(metrics_path);

  CoveragePlotData plot = planPlot(request, poses, trajectory, coverage, combined);
  PlanOutputs outputs;
  // Replanning: what the visited poses and the new trajectory see together.
  const TrajectoryCoverage& searched = combined ? *combined : coverage;
  if (const std::optional<std::string> warning = reachableCoverageWarning(searched)) {
    outputs.warnings.push_back(*warning);
    if (searched.largest_unseen_region)
      plot.unseen_region = searched.largest_unseen_region->outline;
  }
  if (const std::optional<std::string> warning = smoothingLossWarning(searched)) {
    outputs.warnings.push_back(*warning);
  }
  if (const std::optional<std::string> warning =
          wallClearanceWarning(trajectory.min_obstacle_clearance_m, *request.parameters)) {
    outputs.warnings.push_back(*warning);
  }
  CoveragePlot().writePng(plot, plot_path);
  outputs.files = {waypoints_path, trajectory_path, metrics_path, plot_path};
  if (request.frame) {
    for (std::string& path : writeGeoJson(request, written_poses, dir)) {
      outputs.files.push_back(std::move(path));
    }
    writeAutopilotMission(request, trajectory, dir, out, &outputs.files, &outputs.warnings);
  }
  outputs.coverage = coverage.report;
  outputs.turns = trajectory.statistics;
  outputs.traversal_time_s = trajectory.traversal_time_s;
  outputs.min_obstacle_clearance_m = trajectory.min_obstacle_clearance_m;
  outputs.smoothing_loss = searched.lost_to_reference;
  return outputs;
}

}  // namespace kinematic_coverage::core
