// Replanning benchmark: replanning the lake drift scenario (the robot followed the first
// 40 % of the lake_30x30 trajectory, then both obstacles moved by (2, 1) m) with each
// replanning method: validation, cleaning, the remaining area, planning its parts, and
// smoothing the new trajectory. Prints the median, minimum and maximum of N runs; the bar
// is 500 ms for the footprint method.
//
//   replanning_benchmark [--runs N]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "coverage_system/mission/trajectory_pipeline.h"
#include "coverage_system/planner/replanner.h"
#include "polygon_coverage_ros_bridge/base/elapsed_seconds.h"
#include "test/replanning/drift_scenario.h"

namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

/// ms: the bar for replanning and smoothing with the footprint method (median of the runs).
constexpr double kFootprintBarMilliseconds = 500.0;

int main(int argc, char** argv) {
  using namespace kinematic_coverage::core;
  int runs = 21;
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::string(argv[i]) == "--runs") runs = std::max(1, std::atoi(argv[i + 1]));
  }
  try {
    const testing::DriftScenario scenario = testing::lakeDriftScenario(0.4, {2.0, 1.0});
    std::printf("lake_30x30 drift: %zu visited poses, holes moved by (2, 1) m, %d runs each\n",
                scenario.visited.size(), runs);
    std::printf(
        "| method | remaining parts | remaining m^2 | waypoints | replan ms, median (timing) | "
        "smooth ms (timing) | total ms, median (timing) | min ms (timing) | max ms (timing) "
        "|\n|---|---|---|---|---|---|---|---|---|\n");
    double footprint_ms = 0.0;
    for (const char* method : {"footprint", "convex_hull", "concave_hull"}) {
      PlannerParameters parameters = scenario.mission.parameters;
      parameters.replanning_method = method;
      std::vector<double> replan_ms, smooth_ms, total_ms;
      ReplannedMission replanned;
      for (int run = 0; run < runs; ++run) {
        const Clock::time_point start = Clock::now();
        replanned =
            Replanner(parameters).replan(scenario.updated, scenario.visited, scenario.mission.goal);
        replan_ms.push_back(1000.0 * secondsSince(start));
        const Clock::time_point smooth_start = Clock::now();
        const GeneratedTrajectory trajectory =
            TrajectoryPipeline(parameters, replanned.plan.exact_offset_parts)
                .trajectory(replanned.plan.waypoints, replanned.free_area);
        smooth_ms.push_back(1000.0 * secondsSince(smooth_start));
        total_ms.push_back(1000.0 * secondsSince(start));
      }
      auto median = [](std::vector<double> times) {
        std::sort(times.begin(), times.end());
        return times[times.size() / 2];
      };
      std::printf("| %s | %zu | %.1f | %zu | %.2f | %.2f | %.2f | %.2f | %.2f |\n", method,
                  replanned.remaining.parts.size(), replanned.remaining.kept_area_m2,
                  replanned.plan.waypoints.size(), median(replan_ms), median(smooth_ms),
                  median(total_ms), *std::min_element(total_ms.begin(), total_ms.end()),
                  *std::max_element(total_ms.begin(), total_ms.end()));
      if (std::string(method) == "footprint") footprint_ms = median(total_ms);
    }
    std::printf("\nbar: replanning with footprint within %.0f ms (median): %.2f ms, %s\n",
                kFootprintBarMilliseconds, footprint_ms,
                footprint_ms <= kFootprintBarMilliseconds ? "met" : "MISSED");
  } catch (const std::exception& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 1;
  }
  return 0;
}
