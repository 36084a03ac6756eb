// What coverage_repair buys and costs on HardMapGenerator's families
// (test/support/hard_map_generator.h): every map is planned as `coverage_tool plan` plans it
// (planMission) with coverage_repair off and on, and both waypoint paths are measured on the
// coverage report's raster (the repair's own measure). Per family: the maps whose path sees less
// than 99.9 % of the reachable area without and with the repair, the worst reachable coverage with
// it, the median and largest ratio of the repaired path's time cost to the unrepaired one's, and
// the summed planning time of both.
//
// Usage: repair_benchmark [--maps N] [--families comb,spiral,...] [--per-map]
// (maps of seeds 0 to N - 1 per family, default 10; --per-map prints each map's figures on
// stderr).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "bench/support/median.h"
#include "coverage_system/mission/mission_planner.h"
#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/base/elapsed_seconds.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"
#include "test/support/hard_map_generator.h"
#include "trajectory_generation_tools/coverage/coverage_evaluator.h"

namespace {

using kinematic_coverage::bench::median;

using kinematic_coverage::core::CoverageEvaluator;
using kinematic_coverage::core::exactOffsetParts;
using kinematic_coverage::core::FrustumSensor;
using kinematic_coverage::core::Mission;
using kinematic_coverage::core::PlannedMission;
using kinematic_coverage::core::secondsSince;
namespace testing = kinematic_coverage::core::testing;

/// The share of the reachable area a path must see.
constexpr double kBarPercent = 99.9;

struct Options {
  int maps = 10;
  std::vector<testing::MapFamily> families = testing::HardMapGenerator::families();
  bool per_map = false;
};

[[noreturn]] void usage() {
  std::cerr << "usage: repair_benchmark [--maps N] [--families comb,spiral,...] [--per-map]\n";
  std::exit(2);
}

Options parseOptions(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--per-map") {
      options.per_map = true;
      continue;
    }
    if (i + 1 >= argc) usage();
    const std::string value = argv[++i];
    if (flag == "--maps") {
      options.maps = std::atoi(value.c_str());
      if (options.maps < 1) usage();
    } else if (flag == "--families") {
      const auto named = testing::HardMapGenerator::fromNames(value);
      if (!named) usage();
      options.families = *named;
    } else {
      usage();
    }
  }
  return options;
}

/// Reachable coverage (percent) of a plan's waypoint path, as metrics.json measures it.
double reachablePercent(const PlannedMission& planned, const Mission& mission) {
  const CoverageEvaluator evaluator(
      planned.free_area,
      exactOffsetParts(planned.free_area, mission.parameters.wall_distance,
                       planned.plan.offset_parts),
      sensorOf(mission.parameters), kinematic_coverage::core::reportingResolution(),
      kinematic_coverage::core::kReportingGridAngle);
  return evaluator.report(evaluator.seeWaypointPath(planned.plan.waypoints))
      .reachable_coverage_percent;
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parseOptions(argc, argv);
  std::printf(
      "| family | maps | below %.1f %% without | below %.1f %% with | worst with %% | median time "
      "ratio | largest time ratio | plan s without (timing) | plan s with (timing) |\n",
      kBarPercent, kBarPercent);
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const testing::MapFamily family : options.families) {
    const testing::HardMapGenerator generator(family);
    const std::string name = testing::HardMapGenerator::name(family);
    int below_without = 0;
    int below_with = 0;
    double worst_with = 100.0;
    std::vector<double> ratios;
    double seconds_without = 0.0;
    double seconds_with = 0.0;
    int planned = 0;
    for (int seed = 0; seed < options.maps; ++seed) {
      Mission mission = generator.generate(static_cast<std::uint64_t>(seed)).mission;
      mission.parameters.coverage_repair = false;
      auto start = std::chrono::steady_clock::now();
      PlannedMission without;
      try {
        without = kinematic_coverage::core::planMission(mission);
      } catch (const kinematic_coverage::core::UnreachableGoalError& error) {
        std::fprintf(stderr, "refused %s %d: %s\n", name.c_str(), seed, error.what());
        continue;
      }
      ++planned;
      seconds_without += secondsSince(start);
      mission.parameters.coverage_repair = true;
      start = std::chrono::steady_clock::now();
      const PlannedMission with = kinematic_coverage::core::planMission(mission);
      seconds_with += secondsSince(start);
      const double percent_without = reachablePercent(without, mission);
      const double percent_with = reachablePercent(with, mission);
      if (percent_without < kBarPercent) ++below_without;
      if (percent_with < kBarPercent) ++below_with;
      worst_with = std::min(worst_with, percent_with);
      ratios.push_back(with.plan.time_cost_s / without.plan.time_cost_s);
      if (options.per_map) {
        std::fprintf(stderr, "%s %d: %.3f %% -> %.3f %%, time cost %.1f -> %.1f s\n", name.c_str(),
                     seed, percent_without, percent_with, without.plan.time_cost_s,
                     with.plan.time_cost_s);
      }
    }
    std::printf("| %s | %d | %d | %d | %.3f | %.4f | %.3f | %.1f | %.1f |\n", name.c_str(), planned,
                below_without, below_with, worst_with, median(ratios),
                *std::max_element(ratios.begin(), ratios.end()), seconds_without, seconds_with);
    std::fflush(stdout);
  }
  return 0;
}
