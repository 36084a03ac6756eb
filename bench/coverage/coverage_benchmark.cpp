// Coverage evaluation benchmark: evaluating the coverage of the lake_30x30 mission's trajectory
// (smoothed and unsmoothed) as coverage_tool does (measureTrajectoryCoverage on the
// reporting raster): rasterizing the free, offset free and reachable areas, seeing the
// trajectory's poses, and the report. Prints the median of N runs of each stage and the
// minimum and maximum of the total; the bar is 200 ms for the total.
//
//   coverage_benchmark [--runs N] [MISSION.yaml]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "coverage_system/mission/mission_file_reader.h"
#include "coverage_system/mission/mission_planner.h"
#include "coverage_system/mission/trajectory_coverage.h"
#include "coverage_system/mission/trajectory_pipeline.h"
#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"
#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"
#include "trajectory_generation_tools/coverage/coverage_evaluator.h"

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsBetween(Clock::time_point start, Clock::time_point end) {
  return std::chrono::duration<double, std::milli>(end - start).count();
}

double median(std::vector<double> times) {
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

/// Times the stages of measureTrajectoryCoverage's figures on one trajectory (not its
/// heatmap, drawn on a second grid), prints its row and returns the median total (ms).
double benchmark(const char* name, const kinematic_coverage::core::Mission& mission,
                 const kinematic_coverage::core::PlannedMission& planned, int runs) {
  using namespace kinematic_coverage::core;
  const TrajectoryPipeline pipeline(mission.parameters, planned.plan.exact_offset_parts);
  const GeneratedTrajectory trajectory =
      pipeline.trajectory(planned.plan.waypoints, planned.free_area);
  std::vector<Pose2> poses;
  for (const TrajectoryPose& pose : trajectory.poses) poses.push_back(pose.pose());
  const FrustumSensor sensor = sensorOf(mission.parameters);
  const std::vector<PolygonWithHoles> reachable = exactOffsetParts(
      planned.free_area, mission.parameters.wall_distance, planned.plan.offset_parts);

  std::vector<double> raster_ms, seen_ms, report_ms, total_ms;
  CoverageReport report;
  double cell_size = 0.0;
  std::size_t cells = 0;
  for (int run = 0; run < runs; ++run) {
    const Clock::time_point start = Clock::now();
    const CoverageEvaluator evaluator(planned.free_area, reachable, sensor, reportingResolution(),
                                      kReportingGridAngle);
    const Clock::time_point rasterized = Clock::now();
    const SeenArea seen = evaluator.seeTrajectory(poses);
    const Clock::time_point seen_done = Clock::now();
    report = evaluator.report(seen);
    const Clock::time_point end = Clock::now();
    raster_ms.push_back(millisecondsBetween(start, rasterized));
    seen_ms.push_back(millisecondsBetween(rasterized, seen_done));
    report_ms.push_back(millisecondsBetween(seen_done, end));
    total_ms.push_back(millisecondsBetween(start, end));
    cell_size = evaluator.raster().cellSize();
    cells = evaluator.raster().cellCount();
  }
  // The tool's own call, once, to check that the stages above are what it measures.
  const TrajectoryCoverage tool = pipeline.measure(planned.free_area, poses, std::nullopt);
  if (tool.report.coverage_percent != report.coverage_percent) {
    std::fprintf(stderr, "coverage_benchmark: the stages disagree with the tool\n");
    std::exit(1);
  }
  std::printf("| %s | %zu | %.0f cm, %zu | %.4f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f |\n",
              name, poses.size(), 100.0 * cell_size, cells, report.coverage_percent,
              median(raster_ms), median(seen_ms), median(report_ms), median(total_ms),
              *std::min_element(total_ms.begin(), total_ms.end()),
              *std::max_element(total_ms.begin(), total_ms.end()));
  return median(total_ms);
}

/// ms: the bar for evaluating one trajectory's coverage (median of the runs).
constexpr double kBarMilliseconds = 200.0;

}  // namespace

int main(int argc, char** argv) {
  using namespace kinematic_coverage::core;
  int runs = 21;
  std::string mission_path = std::string(KC_MISSIONS_DIR) + "/lake_30x30.yaml";
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--runs" && i + 1 < argc) {
      runs = std::max(1, std::atoi(argv[++i]));
    } else {
      mission_path = arg;
    }
  }
  try {
    std::printf("%s, %d runs each\n", std::filesystem::path(mission_path).filename().c_str(), runs);
    std::printf(
        "| trajectory | poses | raster cells | coverage %% | raster ms (timing) | seen area ms "
        "(timing) | report ms (timing) | total ms, median (timing) | min ms (timing) | max ms "
        "(timing) |\n|---|---|---|---|---|---|---|---|---|---|\n");
    double slowest = 0.0;
    for (const bool smoothing : {true, false}) {
      const Mission mission = MissionFileReader().read(
          mission_path, {smoothing ? "smoothing=true" : "smoothing=false"});
      const PlannedMission planned = planMission(mission);
      slowest = std::max(slowest,
                         benchmark(smoothing ? "smoothed" : "unsmoothed", mission, planned, runs));
    }
    std::printf("\nbar: a trajectory's coverage within %.0f ms (median): %.2f ms at most, %s\n",
                kBarMilliseconds, slowest, slowest <= kBarMilliseconds ? "met" : "MISSED");
  } catch (const std::exception& error) {
    std::fprintf(stderr, "coverage_benchmark: %s\n", error.what());
    return 1;
  }
  return 0;
}
