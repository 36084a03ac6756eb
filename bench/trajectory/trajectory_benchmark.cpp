// Trajectory benchmark: smoothing (Algorithm 1), sampling and timing a 10 000-waypoint
// boustrophedon path (lanes 100 m long and 2 m apart, r = 1 m, 20 rectangular obstacles
// beside the lanes). Prints the path's figures under the three smoothing strategies, then
// the median, minimum and maximum of N runs (default 21) of each stage; the pose buffer is
// reused between runs, as the smooth_trajectory_generator node does. The global strategy's
// smoothing (GlobalPathSmoother) is timed on the same path as a separate row, not part of
// the total, and so is the coverage-safe strategy's (the default), over at most 3 runs: it
// measures the path's coverage on a raster of millions of cells.
//
//   trajectory_benchmark [--runs N]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/base/elapsed_seconds.h"
#include "trajectory_generation_tools/smoothing/global_path_smoother.h"
#include "trajectory_generation_tools/smoothing/path_smoother.h"
#include "trajectory_generation_tools/trajectory/trajectory_sampler.h"
#include "trajectory_generation_tools/trajectory/trajectory_timing.h"

namespace {

/// Runs of the coverage-safe smoothing timed (each takes seconds on this path).
constexpr int kCoverageSafeRuns = 3;

using Clock = std::chrono::steady_clock;
using kinematic_coverage::core::secondsSince;

struct Summary {
  double median, min, max;
};

Summary summarize(std::vector<double> times) {
  std::sort(times.begin(), times.end());
  return {times[times.size() / 2], times.front(), times.back()};
}

}  // namespace

/// ms: the bar for smoothing, sampling and timing together (Algorithm 1), median of the runs.
constexpr double kTotalBarMilliseconds = 20.0;

int main(int argc, char** argv) {
  using kinematic_coverage::core::Point2;
  constexpr int kLanes = 5000;
  int runs = 21;
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::string(argv[i]) == "--runs") runs = std::max(1, std::atoi(argv[i + 1]));
  }
  std::vector<Point2> waypoints;
  for (int i = 0; i < kLanes; ++i) {
    const double x = 2.0 * i;
    waypoints.push_back({x, i % 2 == 0 ? 0.0 : 100.0});
    waypoints.push_back({x, i % 2 == 0 ? 100.0 : 0.0});
  }
  const double width = 2.0 * (kLanes - 1);
  kinematic_coverage::core::PolygonWithHoles area;
  area.hull = {{-10, -10}, {width + 10, -10}, {width + 10, 110}, {-10, 110}};
  for (int k = 0; k < 20; ++k) {
    const double x = width * k / 20.0 + 3.0;
    const double y = k % 2 == 0 ? 103.0 : -7.0;  // beyond the lane ends, clear of the turns
    area.holes.push_back({{x, y}, {x, y + 4}, {x + 6, y + 4}, {x + 6, y}});
  }
  kinematic_coverage::core::PlannerParameters parameters;
  parameters.turning_radius = 1.0;
  const kinematic_coverage::core::TrajectoryOptions options =
      kinematic_coverage::core::trajectoryOptionsOf(parameters);
  const kinematic_coverage::core::TrajectorySampler sampler(options.segment_sampling_distance,
                                                            options.arc_sampling_distance,
                                                            options.rotation_sampling_angle);
  const kinematic_coverage::core::TrajectoryTiming timing(options.vehicle());

  std::vector<double> smooth_ms, sample_ms, time_ms, total_ms, global_ms, safe_ms;
  kinematic_coverage::core::PlannerParameters global_parameters = parameters;
  global_parameters.smoothing_strategy = "global";
  const kinematic_coverage::core::GlobalSmoothingOptions global_options =
      kinematic_coverage::core::globalSmoothingOptionsOf(global_parameters);
  kinematic_coverage::core::PlannerParameters safe_parameters = parameters;
  safe_parameters.smoothing_strategy = "coverage_safe";
  const kinematic_coverage::core::GlobalSmoothingOptions safe_options =
      kinematic_coverage::core::globalSmoothingOptionsOf(safe_parameters);
  kinematic_coverage::core::SmoothedPath global_path;
  kinematic_coverage::core::SmoothedPath safe_path;
  kinematic_coverage::core::SmoothedPath path;
  std::vector<kinematic_coverage::core::TrajectoryPose> poses;
  double traversal_time_s = 0.0;
  for (int run = 0; run < runs; ++run) {
    const Clock::time_point start = Clock::now();
    path =
        kinematic_coverage::core::PathSmoother(area, parameters.turning_radius).smooth(waypoints);
    const Clock::time_point smoothed = Clock::now();
    sampler.sample(path.primitives, poses);
    const Clock::time_point sampled = Clock::now();
    traversal_time_s = timing.assignTimes(path.primitives, poses);
    time_ms.push_back(1000.0 * secondsSince(sampled));
    sample_ms.push_back(1000.0 * std::chrono::duration<double>(sampled - smoothed).count());
    smooth_ms.push_back(1000.0 * std::chrono::duration<double>(smoothed - start).count());
    total_ms.push_back(1000.0 * secondsSince(start));
    const Clock::time_point global_start = Clock::now();
    global_path =
        kinematic_coverage::core::GlobalPathSmoother(area, global_options).smooth(waypoints);
    global_ms.push_back(1000.0 * secondsSince(global_start));
    if (run < kCoverageSafeRuns) {
      const Clock::time_point safe_start = Clock::now();
      safe_path =
          kinematic_coverage::core::GlobalPathSmoother(area, safe_options).smooth(waypoints);
      safe_ms.push_back(1000.0 * secondsSince(safe_start));
    }
  }
  std::vector<kinematic_coverage::core::TrajectoryPose> safe_poses;
  sampler.sample(safe_path.primitives, safe_poses);
  const double safe_time_s = timing.assignTimes(safe_path.primitives, safe_poses);
  std::vector<kinematic_coverage::core::TrajectoryPose> global_poses;
  sampler.sample(global_path.primitives, global_poses);
  const double global_time_s = timing.assignTimes(global_path.primitives, global_poses);
  std::printf(
      "| strategy | waypoints | turns smoothed | primitives | poses | traversal time s |\n"
      "|---|---|---|---|---|---|\n");
  std::printf("| local | %zu | %d / %d | %zu | %zu | %.1f |\n", waypoints.size(),
              path.statistics.turns_smoothed, path.statistics.turns_total, path.primitives.size(),
              poses.size(), traversal_time_s);
  std::printf("| global | %zu | %d / %d | %zu | %zu | %.1f |\n", waypoints.size(),
              global_path.statistics.turns_smoothed, global_path.statistics.turns_total,
              global_path.primitives.size(), global_poses.size(), global_time_s);
  std::printf("| coverage_safe | %zu | %d / %d | %zu | %zu | %.1f |\n\n", waypoints.size(),
              safe_path.statistics.turns_smoothed, safe_path.statistics.turns_total,
              safe_path.primitives.size(), safe_poses.size(), safe_time_s);
  std::printf(
      "| stage | median ms (timing) | min ms (timing) | max ms (timing) |\n|---|---|---|---|\n");
  const std::pair<const char*, std::vector<double>*> stages[] = {
      {"smoothing", &smooth_ms},
      {"sampling", &sample_ms},
      {"timing", &time_ms},
      {"total", &total_ms},
      {"global smoothing", &global_ms},
      {"coverage-safe smoothing", &safe_ms}};
  for (const auto& [name, times] : stages) {
    const Summary summary = summarize(*times);
    std::printf("| %s | %.2f | %.2f | %.2f |\n", name, summary.median, summary.min, summary.max);
  }
  const double total = summarize(total_ms).median;
  std::printf("\nbar: smoothing, sampling and timing within %.0f ms (median): %.2f ms, %s\n",
              kTotalBarMilliseconds, total, total <= kTotalBarMilliseconds ? "met" : "MISSED");
  return 0;
}
