#include "coverage_system/tool/evaluate_command.h"

#include <chrono>
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
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/validation/free_area_builder.h"
#include "polygon_coverage_ros_bridge/validation/polygon_cleaner.h"
#include "trajectory_generation_tools/plot/coverage_plot.h"

namespace kinematic_coverage::core {

std::string EvaluateCommand::usage() {
  return "usage: coverage_tool evaluate MISSION.yaml --trajectory FILE.csv --out DIR\n"
         "                             [--config FILE] [--set name=value ...]\n"
         "  Measures the coverage of a trajectory (a CSV file with a header row; columns\n"
         "  x, y, yaw required, t and kind optional) over the mission's polygon, with the\n"
         "  mission's sensor, and writes DIR/metrics.json and DIR/plot.png. --set overrides a\n"
         "  parameter of config/default.yaml (the value is read as YAML), after the mission\n"
         "  file.\n"
         "  --config FILE reads the parameters of FILE (as config/default.yaml, e.g.\n"
         "  config/thesis.yaml) over the built-in defaults, before the mission file.\n";
}

void EvaluateCommand::run(const std::vector<std::string>& args, std::ostream& out,
                          std::ostream& err) const {
  // Progress goes to `out` as each stage finishes; warnings and notes go to `err` only
  // once the command has succeeded, so that a failure prints just its one error line.
  const std::optional<MissionCommandInput> input = startMissionCommand(
      "evaluate", args, {{"--trajectory", "FILE.csv"}, {"--out", "DIR"}}, usage(), out);
  if (!input) return;
  const std::string& trajectory_path = input->arguments.values.at("--trajectory");
  const std::string& out_dir = input->arguments.values.at("--out");
  const Mission& mission = input->mission;

  auto stage_start = std::chrono::steady_clock::now();
  const std::vector<Pose2> poses = PoseCsvReader().readPoses(trajectory_path);
  double trajectory_length_m = 0.0;
  for (std::size_t i = 1; i < poses.size(); ++i) {
    trajectory_length_m += (poses[i].position() - poses[i - 1].position()).norm();
  }
  out << "read: " << trajectory_path << ": " << poses.size() << " poses, " << trajectory_length_m
      << " m (" << formatSeconds(secondsSince(stage_start)) << ")" << std::endl;

  // The free area and offset free area as `plan` makes them.
  const auto evaluation_start = std::chrono::steady_clock::now();
  const BuiltFreeArea built =
      FreeAreaBuilder(boundarySimplificationOf(mission.parameters)).build(mission.polygon);
  const CleanedPolygon& cleaned = built.cleaned;
  out << "validate: polygon valid (" << formatSeconds(built.validate_s) << ")" << std::endl;
  out << "clean: free area " << area(cleaned.free_area) << " m^2, "
      << cleaned.free_area.holes.size() << " holes, " << cleaned.warnings.size()
      << " cleaning steps (" << formatSeconds(built.clean_s) << ")" << std::endl;

  stage_start = std::chrono::steady_clock::now();
  // The parts that a robot starting where the trajectory starts reaches, as `plan` counts
  // them: a part beyond a gap narrower than gap_clearance counts as unreachable.
  const ReachableOffset offset =
      reachableOffset(cleaned.free_area, planningOptionsOf(mission.parameters),
                      poses.empty() ? mission.start : Point2(poses.front().position()));
  out << "offset: offset free area " << area(offset.parts) << " m^2 in " << offset.parts.size()
      << (offset.parts.size() == 1 ? " part (" : " parts (")
      << formatSeconds(secondsSince(stage_start)) << ")" << std::endl;

  const TrajectoryCoverage coverage =
      measureTrajectoryCoverage(cleaned.free_area, offset.exact_parts, mission.parameters, poses);
  out << "coverage: " << coverageSummary(coverage) << " (" << formatSeconds(coverage.duration_s)
      << ")" << std::endl;
  const double evaluation_time_s = secondsSince(evaluation_start);

  createOutputDirectory(out_dir);
  const std::string metrics_path = (std::filesystem::path(out_dir) / "metrics.json").string();
  JsonObject metrics;
  setCoverageMetrics(coverage.report, metrics);
  metrics.set("pose_count", static_cast<double>(poses.size()))
      .set("trajectory_length_m", trajectory_length_m)
      .set("evaluation_time_s", evaluation_time_s);
  metrics.write(metrics_path);
  const std::string plot_path = (std::filesystem::path(out_dir) / "plot.png").string();
  CoveragePlotData plot;
  plot.free_area = cleaned.free_area;
  plot.offset_parts = offset.parts;
  plot.heatmap = coverage.heatmap;
  plot.trajectory = poses;
  std::ostringstream figures;
  figures.precision(4);
  figures << "coverage " << coverage.report.coverage_percent << " %  |  loss "
          << coverage.report.coverage_loss_percent << " %  |  " << poses.size() << " poses  |  "
          << formatLength(trajectory_length_m);
  plot.title_lines = {"Coverage of " + std::filesystem::path(trajectory_path).filename().string(),
                      figures.str()};
  CoveragePlot().writePng(plot, plot_path);

  std::ostringstream notes;
  for (const std::string& warning : cleaned.warnings) notes << "warning: " << warning << "\n";
  err << notes.str();
  out << "wrote " << metrics_path << " " << plot_path << "\n";
}

}  // namespace kinematic_coverage::core
