#include "coverage_system/tool/simulate_command.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>

#include "coverage_system/mission/pose_csv_reader.h"
#include "coverage_system/mission/trajectory_coverage.h"
#include "coverage_system/parameters/stage_options.h"
#include "coverage_system/planner/reachable_offset_parts.h"
#include "coverage_system/tool/command_line.h"
#include "coverage_system/tool/coverage_metrics.h"
#include "coverage_system/tool/json_object.h"
#include "polygon_coverage_ros_bridge/base/elapsed_seconds.h"
#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/base/text_file_writer.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/validation/free_area_builder.h"
#include "polygon_coverage_ros_bridge/validation/polygon_cleaner.h"
#include "trajectory_generation_tools/plot/coverage_plot.h"
#include "trajectory_generation_tools/plot/tracking_error_plot.h"
#include "trajectory_generation_tools/simulation/driven_path_clearance.h"
#include "trajectory_generation_tools/simulation/pose_sequence_timing.h"
#include "trajectory_generation_tools/simulation/robot_model_warnings.h"
#include "trajectory_generation_tools/simulation/robot_simulator.h"

namespace kinematic_coverage::core {
namespace {

/// `actual.csv` (docs/REFERENCE.md, File formats): the pose and the tracking errors of
/// every recorded step.
std::string actualCsv(const std::vector<SimulationStep>& steps) {
  std::string text = "t,x,y,yaw,error_m,error_x_m,error_y_m,target_error_m\n";
  for (const SimulationStep& step : steps) {
    for (const double value :
         {step.t, step.pose.x, step.pose.y, step.pose.yaw, step.tracking_error_m,
          step.tracking_error_x_m, step.tracking_error_y_m}) {
      text += formatRoundTrip(value) + ",";
    }
    text += formatRoundTrip(step.target_error_m) + "\n";
  }
  return text;
}

/// `tracking_error_percentiles_m` or `tracking_error_target_percentiles_m`: "1" ... "99"
/// to metres, as in Table 4.2.
JsonObject percentileObject(const TrackingErrorStatistics& tracking) {
  JsonObject percentiles;
  for (std::size_t i = 0; i < kTrackingErrorPercentiles.size(); ++i) {
    percentiles.set(std::to_string(kTrackingErrorPercentiles[i]), tracking.percentiles_m[i]);
  }
  return percentiles;
}

/// The poses the robot model reached, one per recorded step.
std::vector<Pose2> actualPoses(const SimulationResult& simulation) {
  std::vector<Pose2> actual;
  actual.reserve(simulation.steps.size());
  for (const SimulationStep& step : simulation.steps) actual.push_back(step.pose);
  return actual;
}

/// metrics.json of `simulate` (docs/REFERENCE.md, Metrics).
JsonObject simulationMetrics(const SimulationResult& simulation, const TrajectoryCoverage& coverage,
                             const DrivenPathClearance& clearance) {
  const TrackingErrorStatistics& tracking = simulation.tracking;
  const AxisErrorStatistics& axes = simulation.tracking_axes;
  const TrackingErrorStatistics& target = simulation.target_tracking;
  JsonObject metrics;
  metrics.set("traversal_time_s", simulation.traversal_time_s)
      .set("tracking_error_sum_m", tracking.sum_m)
      .set("tracking_error_mean_m", tracking.mean_m)
      .set("tracking_error_percentiles_m", percentileObject(tracking))
      .set("tracking_error_x_mean_m", axes.x_mean_m)
      .set("tracking_error_y_mean_m", axes.y_mean_m)
      .set("tracking_error_x_max_m", axes.x_max_m)
      .set("tracking_error_y_max_m", axes.y_max_m)
      .set("tracking_error_target_sum_m", target.sum_m)
      .set("tracking_error_target_mean_m", target.mean_m)
      .set("tracking_error_target_percentiles_m", percentileObject(target));
  if (const auto& time_matched = simulation.time_matched_tracking) {
    metrics.set("tracking_error_time_matched_sum_m", time_matched->sum_m)
        .set("tracking_error_time_matched_mean_m", time_matched->mean_m)
        .set("tracking_error_time_matched_percentiles_m", percentileObject(*time_matched));
  }
  metrics.set("reference_excess_time_s", simulation.reference_excess.duration_s);
  metrics.set("tracking_error_2hz_sum_m", simulation.sampled_tracking.sum_m)
      .set("tracking_error_2hz_mean_m", simulation.sampled_tracking.mean_m)
      .set("tracking_error_target_2hz_sum_m", simulation.sampled_target_tracking.sum_m)
      .set("tracking_error_target_2hz_mean_m", simulation.sampled_target_tracking.mean_m);
  if (const auto& time_matched = simulation.sampled_time_matched_tracking) {
    metrics.set("tracking_error_time_matched_2hz_sum_m", time_matched->sum_m)
        .set("tracking_error_time_matched_2hz_mean_m", time_matched->mean_m);
  }
  if (std::isfinite(clearance.min_clearance_m)) {
    metrics.set("driven_min_clearance_m", clearance.min_clearance_m);
  }
  metrics.set("driven_obstacle_time_s", clearance.obstacle_time_s)
      .set("driven_outside_hull_time_s", clearance.outside_hull_time_s);
  setCoverageMetrics(coverage.report, metrics);
  return metrics;
}

/// The warning for a reference that asked for more than the vehicle can do.
std::string referenceExcessText(const ReferenceExcess& excess, std::size_t pose_count) {
  std::ostringstream text;
  text << "the trajectory asks for more than the vehicle can do for " << excess.duration_s
       << " s of the run, first at t = " << excess.first_t << " s near ("
       << excess.first_position.x() << ", " << excess.first_position.y() << ") on the way to pose "
       << excess.first_pose + 1 << " of " << pose_count << ": " << excess.first_demand
       << "; the robot lags its reference there";
  return text.str();
}

/// The `clearance:` line of `simulate`.
std::string clearanceSummary(const DrivenPathClearance& clearance) {
  std::ostringstream text;
  if (clearance.contact()) {
    text << "CONTACT: the driven path entered an obstacle or left the hull (first at t = "
         << clearance.first_contact_t << " s)";
  } else if (std::isfinite(clearance.min_clearance_m)) {
    text << "the driven path came within " << clearance.min_clearance_m
         << " m of a wall or an obstacle";
  } else {
    text << "no driven pose lies inside the free area";
  }
  return text.str();
}

/// plot.png of `simulate` without its areas and first title line: the heatmap of the
/// actual poses, the desired trajectory, the actual path coloured by tracking error and
/// the figures line.
CoveragePlotData simulationPlot(const SimulationResult& simulation,
                                const TrajectoryCoverage& coverage,
                                const std::vector<Pose2>& desired,
                                const std::vector<Pose2>& actual) {
  const TrackingErrorStatistics& tracking = simulation.tracking;
  CoveragePlotData plot;
  plot.heatmap = coverage.heatmap;
  plot.trajectory = desired;
  plot.actual_path = actual;
  plot.actual_errors.reserve(simulation.steps.size());
  for (const SimulationStep& step : simulation.steps) {
    plot.actual_errors.push_back(step.tracking_error_m);
  }
  std::ostringstream figures;
  figures.precision(4);
  figures << formatDuration(simulation.traversal_time_s) << "  |  tracking error sum "
          << tracking.sum_m << " m, mean " << tracking.mean_m << " m, p99 "
          << tracking.percentiles_m.back() << " m  |  coverage " << coverage.report.coverage_percent
          << " %";
  plot.title_lines = {figures.str()};
  return plot;
}

/// Arrows of poses.png per simulated second at most, and in all.
constexpr double kPoseArrowsPerSecond = 1.0;
constexpr std::size_t kMaxPoseArrows = 1500;

/// poses.png of `simulate` without its areas: the desired trajectory in red and the
/// driven poses as black arrows (the thesis's Fig. 4.3).
CoveragePlotData posesPlot(const SimulationResult& simulation, const std::vector<Pose2>& desired,
                           double sim_dt) {
  CoveragePlotData plot;
  plot.trajectory = desired;
  const std::size_t steps = simulation.steps.size();
  const std::size_t stride = std::max<std::size_t>(
      {1, static_cast<std::size_t>(std::lround(1.0 / (kPoseArrowsPerSecond * sim_dt))),
       (steps + kMaxPoseArrows - 1) / kMaxPoseArrows});
  for (std::size_t i = 0; i < steps; i += stride) {
    plot.actual_pose_arrows.push_back(simulation.steps[i].pose);
  }
  return plot;
}

/// errors.png of `simulate`: the step errors, their histograms and normal fits.
TrackingErrorPlotData errorsPlot(const SimulationResult& simulation) {
  TrackingErrorPlotData plot;
  for (std::size_t i = 1; i < simulation.steps.size(); ++i) {
    const SimulationStep& step = simulation.steps[i];
    plot.t.push_back(step.t);
    plot.error.push_back(step.tracking_error_m);
    plot.error_x.push_back(step.tracking_error_x_m);
    plot.error_y.push_back(step.tracking_error_y_m);
  }
  if (plot.t.empty()) {
    const SimulationStep& start = simulation.steps.front();
    plot.t.push_back(start.t);
    plot.error.push_back(start.tracking_error_m);
    plot.error_x.push_back(start.tracking_error_x_m);
    plot.error_y.push_back(start.tracking_error_y_m);
  }
  return plot;
}

/// Writes plot.png, poses.png and errors.png into `dir`, titled by `title`.
void writeSimulationFigures(const std::filesystem::path& dir, const std::string& title,
                            const SimulationResult& simulation, const TrajectoryCoverage& coverage,
                            const std::vector<Pose2>& desired, const CleanedPolygon& cleaned,
                            const ReachableOffset& offset, double sim_dt) {
  CoveragePlotData plot = simulationPlot(simulation, coverage, desired, actualPoses(simulation));
  CoveragePlotData poses = posesPlot(simulation, desired, sim_dt);
  for (CoveragePlotData* figure : {&plot, &poses}) {
    figure->free_area = cleaned.free_area;
    figure->offset_parts = offset.parts;
  }
  plot.title_lines.insert(plot.title_lines.begin(), title);
  poses.title_lines = plot.title_lines;
  CoveragePlot().writePng(plot, (dir / "plot.png").string());
  CoveragePlot().writePng(poses, (dir / "poses.png").string());
  TrackingErrorPlotData errors = errorsPlot(simulation);
  errors.title_lines = plot.title_lines;
  TrackingErrorPlot().writePng(errors, (dir / "errors.png").string());
}

}  // namespace

std::string SimulateCommand::usage() {
  return "usage: coverage_tool simulate MISSION.yaml --trajectory FILE.csv --out DIR\n"
         "                             [--config FILE] [--set name=value ...]\n"
         "  A robot model follows the trajectory's poses (a CSV file with a header row;\n"
         "  columns x, y, yaw required, t and kind optional) from rest at the first pose,\n"
         "  with the mission's robot parameters (vehicle_model, dynamic by default, with its\n"
         "  mass to yaw_rate_loop_gain; v_max, a_max, yaw_rate_max, yaw_gain,\n"
         "  position_gain, position_tolerance, yaw_tolerance, current_x, current_y, the\n"
         "  disturbances current_sigma, current_time_constant, navigation_sigma,\n"
         "  navigation_time_constant and disturbance_seed, sim_dt, sim_time_limit), and writes "
         "DIR/actual.csv (t,x,y,yaw and the tracking errors\n"
         "  error_m,error_x_m,error_y_m,target_error_m per step), DIR/metrics.json\n"
         "  (traversal time, tracking errors, the driven path's clearance from walls\n"
         "  and obstacles, coverage of the actual poses),\n"
         "  DIR/plot.png (the driven path over the heatmap), DIR/poses.png (desired\n"
         "  trajectory and actual poses) and DIR/errors.png (error histograms, normal fits\n"
         "  and errors over time). --set overrides a parameter of config/default.yaml (the value\n"
         "  is read as YAML), after the mission file.\n"
         "  --config FILE reads the parameters of FILE (as config/default.yaml, e.g.\n"
         "  config/thesis.yaml) over the built-in defaults, before the mission file.\n";
}

namespace {

/// A trajectory file's poses and, for the controllers that follow them, their times.
struct TimedPoses {
  std::vector<Pose2> poses;
  std::vector<double> times;
};

/// The poses of the file at `path` and their t column, or where the file has none and the
/// controller follows times (usesTrajectoryTimes), times from the planner's velocity model (said on
/// `out`).
TimedPoses readTimedPoses(const std::string& path, const RobotModel& robot, std::ostream& out) {
  const PoseTable table = PoseCsvReader().read(path);
  TimedPoses timed;
  timed.poses.reserve(table.rows.size());
  for (const PoseRecord& row : table.rows) {
    timed.poses.push_back(row.pose);
    if (table.has_time) timed.times.push_back(row.t);
  }
  if (usesTrajectoryTimes(robot.controller) && !table.has_time) {
    timed.times = PoseSequenceTiming(robot.vehicle).times(timed.poses);
    out << "timed: " << path << " has no t column: its poses are timed by the planner's "
        << "velocity model (" << timed.times.back() << " s)" << std::endl;
  }
  return timed;
}

}  // namespace

void SimulateCommand::run(const std::vector<std::string>& args, std::ostream& out,
                          std::ostream& err) const {
  const std::optional<MissionCommandInput> input = startMissionCommand(
      "simulate", args, {{"--trajectory", "FILE.csv"}, {"--out", "DIR"}}, usage(), out);
  if (!input) return;
  const std::string& trajectory_path = input->arguments.values.at("--trajectory");
  const std::string& out_dir = input->arguments.values.at("--out");
  const Mission& mission = input->mission;

  auto stage_start = std::chrono::steady_clock::now();
  const RobotModel robot = robotModelOf(mission.parameters);
  const TimedPoses trajectory = readTimedPoses(trajectory_path, robot, out);
  const std::vector<Pose2>& desired = trajectory.poses;
  out << "read: " << trajectory_path << ": " << desired.size() << " poses ("
      << formatSeconds(secondsSince(stage_start)) << ")" << std::endl;

  // The free area and offset free area as `plan` makes them, for the
  // coverage of the actual poses.
  stage_start = std::chrono::steady_clock::now();
  const CleanedPolygon cleaned =
      FreeAreaBuilder(boundarySimplificationOf(mission.parameters)).build(mission.polygon).cleaned;
  const ReachableOffset offset =
      reachableOffset(cleaned.free_area, planningOptionsOf(mission.parameters),
                      desired.empty() ? mission.start : Point2(desired.front().position()));
  out << "area: free area " << area(cleaned.free_area) << " m^2, offset free area "
      << area(offset.parts) << " m^2 (" << formatSeconds(secondsSince(stage_start)) << ")"
      << std::endl;

  stage_start = std::chrono::steady_clock::now();
  const SimulationResult simulation = RobotSimulator(robot).simulate(desired, trajectory.times);
  const TrackingErrorStatistics& tracking = simulation.tracking;
  out << "simulate: the " << mission.parameters.vehicle_model << " vehicle reached the last of "
      << desired.size() << " poses after " << simulation.traversal_time_s << " s in "
      << simulation.steps.size() - 1 << " steps; tracking error sum " << tracking.sum_m
      << " m, mean " << tracking.mean_m << " m, 99th percentile " << tracking.percentiles_m.back()
      << " m; target error sum " << simulation.target_tracking.sum_m << " m ("
      << formatSeconds(secondsSince(stage_start)) << ")" << std::endl;

  const DrivenPathClearance clearance =
      measureDrivenPathClearance(simulation.steps, cleaned.free_area, mission.parameters.sim_dt);
  out << "clearance: " << clearanceSummary(clearance) << std::endl;

  const std::vector<Pose2> actual = actualPoses(simulation);
  const TrajectoryCoverage coverage =
      measureTrajectoryCoverage(cleaned.free_area, offset.exact_parts, mission.parameters, actual);
  out << "coverage: " << coverageSummary(coverage) << " (" << formatSeconds(coverage.duration_s)
      << ")" << std::endl;

  createOutputDirectory(out_dir);
  const std::filesystem::path dir(out_dir);
  const std::string actual_path = (dir / "actual.csv").string();
  const std::string metrics_path = (dir / "metrics.json").string();
  writeTextFile(actual_path, actualCsv(simulation.steps));
  simulationMetrics(simulation, coverage, clearance).write(metrics_path);
  writeSimulationFigures(
      dir,
      "Simulated robot on " + std::filesystem::path(trajectory_path).filename().string() + " (" +
          std::filesystem::path(input->arguments.mission_path).filename().string() + ")",
      simulation, coverage, desired, cleaned, offset, mission.parameters.sim_dt);

  std::ostringstream notes;
  for (const std::string& warning : cleaned.warnings) notes << "warning: " << warning << "\n";
  for (const std::string& warning : robotModelWarnings(robot)) {
    notes << "warning: " << warning << "\n";
  }
  if (simulation.reference_excess.duration_s > 0.0) {
    notes << "warning: " << referenceExcessText(simulation.reference_excess, desired.size())
          << "\n";
  }
  if (clearance.contact()) {
    notes << "warning: the robot drove into an obstacle or out through the hull, first at t = "
          << clearance.first_contact_t << " s at (" << clearance.first_contact.x() << ", "
          << clearance.first_contact.y() << "): " << clearance.obstacle_time_s
          << " s inside obstacles, " << clearance.outside_hull_time_s
          << " s outside the hull; a larger wall_distance or a calmer lake is needed\n";
  }
  err << notes.str();
  out << "wrote " << actual_path << " " << metrics_path << " " << (dir / "plot.png").string() << " "
      << (dir / "poses.png").string() << " " << (dir / "errors.png").string() << "\n";
}

}  // namespace kinematic_coverage::core
