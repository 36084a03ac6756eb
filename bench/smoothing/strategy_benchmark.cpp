// Smoothing strategies per map family: what each sees and what it costs, end to end as
// `coverage_tool plan` runs (validate, clean, plan, trajectory, coverage evaluation, and
// writing waypoints.csv, trajectory.csv, metrics.json and plot.png, into a temporary
// directory that is removed afterwards).
// Each map of HardMapGenerator's families (test/support/hard_map_generator.h) is planned
// once with its parameters; each strategy turns the waypoints into a trajectory whose
// coverage is measured as plan's metrics.json reports it:
//  - local: the thesis's Algorithm 1 (`smoothing_strategy: local`);
//  - global: every corner's smoothing chosen jointly (`smoothing_strategy: global`);
//  - global+coverage: global with `coverage_preserving: true`;
//  - coverage_safe: the global programme keeping the sharp path's coverage
//    (`smoothing_strategy: coverage_safe`);
//  - coverage_safe (free): the same keeping all of the free area the sharp path sees, the
//    wall band beyond the reachable area included (`coverage_safe_area: free`);
//  - default: the parameters' defaults, named after the strategy they select;
//  - unsmoothed: `smoothing: false`, the reference for coverage and traversal time.
// Table 1, per family, batch and strategy: the median and worst share of the reachable area
// seen, the maps under 99.9 %, the largest drop below the unsmoothed trajectory's share
// (points), the median ratio of traversal time to the unsmoothed trajectory's, and the
// summed end-to-end wall time (planning + trajectory + coverage + files) with its ratio to the
// unsmoothed runs' and the maps over 1.3 times the unsmoothed run plus 0.5 s.
// Table 2, the unsmoothed plan per family and batch: the median time cost and traversal time.
// Table 3, turns smoothed per strategy on lake_30x30 and on LakeMapGenerator's lakes
// (test/support/lake_map_generator.h): 30 m squares with two obstacles of other shapes and
// places.
// Table 4, per family, batch and smoothing strategy: what the smoothed trajectory fails to
// see of what the unsmoothed trajectory sees (metrics.json's smoothing_lost_area_m2, as a
// share of the free area): median, worst, the maps over plan's warning threshold, and the
// largest reachable part.
// Table 5, per family, batch and lake set, for the default and the unsmoothed trajectory:
// whether the trajectory keeps the wall distance (metrics.json's min_obstacle_clearance_m,
// which leaves out the way in from a start in the wall band and out to such a goal): the
// least ratio of closest approach to wall_distance and the maps nearer than wall_distance
// by more than kClearanceTolerance; the share of turns smoothed, the median traversal time
// and its median ratio to the unsmoothed trajectory's.
// Table 6, per family, batch and lake set: where the default's traversal time goes. The
// median traversal time of the map planned with `coverage_repair: false` (unsmoothed, and
// with the default smoothing under the thesis's no-contact check, `smoothing_clearance: 0`),
// then of the default plan (unsmoothed, the no-contact check, the default), and the share
// of turns smoothed under the no-contact check and by default.
//
// Usage: strategy_benchmark [--maps N[,N...]] [--families comb,spiral,...] [--lakes 10]
//                           [--per-map]
// Each N is a batch of maps per family, seeds from 0: the first batch has rows of its own
// ("comb, maps 1-5"), so that a short run prints the first rows of a long one, and with
// several batches the family's rows over all of them follow ("comb, all 50 maps"; default
// --maps 5,45). A label names the maps whose goal the planner refuses ("touching_holes,
// all 50 maps, 1 refused"). --per-map prints each map's figures on stderr.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <functional>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "bench/support/median.h"
#include "coverage_system/mission/mission_file_reader.h"
#include "coverage_system/mission/mission_planner.h"
#include "coverage_system/mission/trajectory_coverage.h"
#include "coverage_system/tool/plan_output_writer.h"
#include "polygon_coverage_ros_bridge/base/elapsed_seconds.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "test/support/hard_map_generator.h"
#include "test/support/lake_map_generator.h"

namespace kinematic_coverage::core {
namespace {

using kinematic_coverage::bench::median;

using Clock = std::chrono::steady_clock;

/// The reachable-coverage bar of a searched map (percent) and the wall-time allowance of a
/// smoothed run over the unsmoothed one: kWallFactor times it plus kWallSlack seconds.
constexpr double kCoverageBarPercent = 99.9;
/// The bar of the lake-like maps: the default smooths at least this share (%) of their
/// turns in all.
constexpr double kLakeTurnsBarPercent = 90.0;
constexpr double kWallFactor = 1.3;
constexpr double kWallSlack = 0.5;

/// The strategies in column order; the last is the unsmoothed reference.
enum Strategy {
  kLocal,
  kGlobal,
  kGlobalCoverage,
  kCoverageSafe,
  kCoverageSafeFree,
  kDefault,
  kUnsmoothed,
  kStrategies
};

struct Options {
  std::vector<int> batches = {5, 45};
  std::vector<testing::MapFamily> families = testing::HardMapGenerator::families();
  int lakes = 10;
  bool per_map = false;
};

[[noreturn]] void usage() {
  std::cerr << "usage: strategy_benchmark [--maps N[,N...]] [--families comb,spiral,...] "
               "[--lakes 10] [--per-map]\n";
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
      options.batches.clear();
      std::istringstream sizes(value);
      std::string size;
      while (std::getline(sizes, size, ',')) {
        options.batches.push_back(std::atoi(size.c_str()));
        if (options.batches.back() <= 0) usage();
      }
    } else if (flag == "--families") {
      const auto named = testing::HardMapGenerator::fromNames(value);
      if (!named) usage();
      options.families = *named;
    } else if (flag == "--lakes") {
      options.lakes = std::atoi(value.c_str());
      if (options.lakes < 0) usage();
    } else {
      usage();
    }
  }
  if (options.batches.empty() || options.families.empty()) usage();
  return options;
}

/// The parameters of a strategy, from a map's.
PlannerParameters withStrategy(PlannerParameters parameters, Strategy strategy) {
  switch (strategy) {
    case kLocal:
      parameters.smoothing_strategy = "local";
      parameters.coverage_preserving = false;
      break;
    case kGlobal:
    case kGlobalCoverage:
      parameters.smoothing_strategy = "global";
      parameters.coverage_preserving = strategy == kGlobalCoverage;
      break;
    case kCoverageSafe:
    case kCoverageSafeFree:
      parameters.smoothing_strategy = "coverage_safe";
      parameters.coverage_preserving = false;
      parameters.coverage_safe_area = strategy == kCoverageSafeFree ? "free" : "reachable";
      break;
    case kUnsmoothed:
      parameters.smoothing = false;
      break;
    default:
      break;
  }
  return parameters;
}

/// The strategy's name in the tables; the default's names what it selects.
std::string strategyName(Strategy strategy) {
  switch (strategy) {
    case kLocal:
      return "local";
    case kGlobal:
      return "global";
    case kGlobalCoverage:
      return "global+coverage";
    case kCoverageSafe:
      return "coverage_safe";
    case kCoverageSafeFree:
      return "coverage_safe (free)";
    case kDefault: {
      const PlannerParameters defaults;
      return "default (" + defaults.smoothing_strategy +
             (defaults.coverage_preserving ? "+coverage)" : ")");
    }
    default:
      return "unsmoothed";
  }
}

/// A directory removed with everything in it when this goes out of scope.
struct ScratchDirectory {
  std::string path;
  ~ScratchDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

/// One strategy's figures on one map.
struct Run {
  double reachable_percent = 0.0;
  double traversal_time_s = 0.0;
  double wall_s = 0.0;  ///< planning + trajectory + coverage + writing the files
  int turns_smoothed = 0;
  int turns_total = 0;
  double min_clearance_m = 0.0;  ///< metrics.json's min_obstacle_clearance_m
  /// What the trajectory fails to see of what the unsmoothed one sees (zero unsmoothed).
  LostArea lost;
};

/// Every strategy's run on one mission, planned once.
struct MapRuns {
  Run runs[kStrategies];
  /// Table 6's runs: the default smoothing with the thesis's no-contact check
  /// (`smoothing_clearance: 0`) on the same plan, and, on the plan made without coverage
  /// repair, the unsmoothed trajectory and that no-contact smoothing.
  Run no_contact;
  Run unrepaired_unsmoothed;
  Run unrepaired_no_contact;
  double time_cost_s = 0.0;    ///< the plan's
  double wall_distance = 0.0;  ///< m, the map's
};

/// One trajectory of `planned` with `parameters`, written as plan writes it.
Run runTrajectory(const PlannerParameters& parameters, const Mission& mission,
                  const PlannedMission& planned, double planning_s, const std::string& name,
                  const std::string& out_dir) {
  PlanOutputRequest request;
  request.parameters = &parameters;
  request.free_area = &planned.free_area;
  request.plan = &planned.plan;
  request.planning_time_s = planning_s;
  request.start = mission.start;
  request.goal = mission.goal;
  request.title = "strategy_benchmark: " + name;
  std::ostringstream progress;
  const auto started = Clock::now();
  const PlanOutputs outputs = writePlanOutputs(request, out_dir, progress);
  Run run;
  run.wall_s = planning_s + secondsSince(started);
  run.reachable_percent = outputs.coverage.reachable_coverage_percent;
  run.traversal_time_s = outputs.traversal_time_s;
  run.turns_smoothed = outputs.turns.turns_smoothed;
  run.turns_total = outputs.turns.turns_total;
  run.min_clearance_m = outputs.min_obstacle_clearance_m;
  if (outputs.smoothing_loss) run.lost = *outputs.smoothing_loss;
  return run;
}

/// Table 6's runs of `mission` (MapRuns), `planned` being its default plan.
void runTimeParts(const Mission& mission, const PlannedMission& planned, double planning_s,
                  const std::string& out_dir, MapRuns& result) {
  PlannerParameters no_contact = mission.parameters;
  no_contact.smoothing_clearance = 0.0;
  result.no_contact =
      runTrajectory(no_contact, mission, planned, planning_s, "no-contact check", out_dir);
  Mission unrepaired = mission;
  unrepaired.parameters.coverage_repair = false;
  const auto started = Clock::now();
  const PlannedMission unrepaired_plan = planMission(unrepaired);
  const double unrepaired_s = secondsSince(started);
  no_contact.coverage_repair = false;
  result.unrepaired_no_contact = runTrajectory(no_contact, unrepaired, unrepaired_plan,
                                               unrepaired_s, "no-contact, no repair", out_dir);
  result.unrepaired_unsmoothed =
      runTrajectory(withStrategy(unrepaired.parameters, kUnsmoothed), unrepaired, unrepaired_plan,
                    unrepaired_s, "unsmoothed, no repair", out_dir);
}

MapRuns runMap(const Mission& mission, const std::string& out_dir) {
  MapRuns result;
  const auto planning_started = Clock::now();
  const PlannedMission planned = planMission(mission);
  const double planning_s = secondsSince(planning_started);
  result.time_cost_s = planned.plan.time_cost_s;
  result.wall_distance = mission.parameters.wall_distance;
  for (int s = 0; s < kStrategies; ++s) {
    const PlannerParameters parameters = withStrategy(mission.parameters, Strategy(s));
    // The default selects one of the strategies before it: the same run.
    if (s == kDefault) {
      const bool free = parameters.coverage_safe_area == "free";
      const int same = parameters.smoothing_strategy == "local" ? kLocal
                       : parameters.smoothing_strategy == "coverage_safe"
                           ? (free ? kCoverageSafeFree : kCoverageSafe)
                       : parameters.coverage_preserving ? kGlobalCoverage
                                                        : kGlobal;
      result.runs[s] = result.runs[same];
      continue;
    }
    result.runs[s] =
        runTrajectory(parameters, mission, planned, planning_s, strategyName(Strategy(s)), out_dir);
  }
  runTimeParts(mission, planned, planning_s, out_dir, result);
  return result;
}

/// A labelled set of maps of table 1 ("comb, maps 1-5"), for the tables after it.
struct MapSet {
  std::string label;
  std::vector<MapRuns> maps;
};

/// Table 2: the unsmoothed plan's median time cost and traversal time per set.
void printBaselineTable(const std::vector<MapSet>& sets) {
  std::printf(
      "\n| family, maps | maps | unsmoothed plan: time cost s, median | unsmoothed trajectory: "
      "traversal time s, median |\n|---|---:|---:|---:|\n");
  for (const MapSet& set : sets) {
    std::vector<double> costs;
    std::vector<double> times;
    for (const MapRuns& map : set.maps) {
      costs.push_back(map.time_cost_s);
      times.push_back(map.runs[kUnsmoothed].traversal_time_s);
    }
    std::printf("| %s | %zu | %.2f | %.2f |\n", set.label.c_str(), set.maps.size(), median(costs),
                median(times));
  }
}

/// Table 4: per set and smoothing strategy, what the trajectory fails to see of what the
/// unsmoothed trajectory sees.
void printLossTable(const std::vector<MapSet>& sets) {
  std::printf(
      "\n| family, maps | strategy | seen unsmoothed, unseen smoothed, %% of the free area: "
      "median | worst | maps over %.1f %% (plan warns) | largest reachable part, m^2 |\n"
      "|---|---|---:|---:|---:|---:|\n",
      kSmoothingLossWarningPercent);
  for (const MapSet& set : sets) {
    for (int s = 0; s < kStrategies; ++s) {
      if (s == kUnsmoothed) continue;
      std::vector<double> lost;
      double reachable = 0.0;
      int warned = 0;
      for (const MapRuns& map : set.maps) {
        const LostArea& run = map.runs[s].lost;
        lost.push_back(run.percent_of_free_area);
        reachable = std::max(reachable, run.reachable_area_m2);
        warned += run.percent_of_free_area > kSmoothingLossWarningPercent ? 1 : 0;
      }
      std::printf("| %s | %s | %.3f | %.3f | %d | %.3f |\n", set.label.c_str(),
                  strategyName(Strategy(s)).c_str(), median(lost),
                  *std::max_element(lost.begin(), lost.end()), warned, reachable);
    }
  }
}

/// The run of a map that a table's column shows.
using RunOf = std::function<const Run&(const MapRuns&)>;

/// The share (%) of the turns of `maps` that their runs `run_of` smoothed.
double turnsSmoothedPercent(const std::vector<MapRuns>& maps, const RunOf& run_of) {
  int smoothed = 0;
  int total = 0;
  for (const MapRuns& map : maps) {
    smoothed += run_of(map).turns_smoothed;
    total += run_of(map).turns_total;
  }
  return total > 0 ? 100.0 * smoothed / total : 100.0;
}

/// Table 5: per set, for the default and the unsmoothed trajectory, whether it keeps the
/// wall distance, its turns smoothed and its traversal time.
void printClearanceTable(const std::vector<MapSet>& sets) {
  std::printf(
      "\n| family, maps | strategy | maps | closest approach / wall_distance, least | maps "
      "nearer than wall_distance | turns smoothed %% | traversal time s, median | traversal "
      "time ratio to unsmoothed, median |\n|---|---|---:|---:|---:|---:|---:|---:|\n");
  for (const MapSet& set : sets) {
    for (const Strategy strategy : {kDefault, kUnsmoothed}) {
      double least = std::numeric_limits<double>::infinity();
      int nearer = 0;
      std::vector<double> times;
      std::vector<double> ratios;
      for (const MapRuns& map : set.maps) {
        const Run& run = map.runs[strategy];
        if (map.wall_distance > 0.0 && std::isfinite(run.min_clearance_m)) {
          least = std::min(least, run.min_clearance_m / map.wall_distance);
          nearer += keepsClearance(run.min_clearance_m, map.wall_distance) ? 0 : 1;
        }
        times.push_back(run.traversal_time_s);
        ratios.push_back(run.traversal_time_s / map.runs[kUnsmoothed].traversal_time_s);
      }
      std::printf(
          "| %s | %s | %zu | %.3f | %d | %.1f | %.2f | %.3f |\n", set.label.c_str(),
          strategyName(strategy).c_str(), set.maps.size(), least, nearer,
          turnsSmoothedPercent(
              set.maps, [&](const MapRuns& map) -> const Run& { return map.runs[strategy]; }),
          median(times), median(ratios));
    }
  }
}

/// Table 6: per set, where the default's traversal time goes: the median traversal time of
/// the plan made without coverage repair (unsmoothed, and smoothed with the no-contact
/// check), of the default plan (unsmoothed, no-contact check, default), and the share of
/// turns smoothed with either check.
void printTimePartsTable(const std::vector<MapSet>& sets) {
  std::printf(
      "\n| family, maps | maps | repair off: unsmoothed, traversal time s, median | repair "
      "off: no-contact check | unsmoothed | no-contact check | default | turns smoothed %%: "
      "no-contact check | turns smoothed %%: default |\n|---|---:|---:|---:|---:|---:|---:|---:|"
      "---:|\n");
  const RunOf no_contact = [](const MapRuns& map) -> const Run& { return map.no_contact; };
  const RunOf by_default = [](const MapRuns& map) -> const Run& { return map.runs[kDefault]; };
  const std::vector<RunOf> columns = {
      [](const MapRuns& map) -> const Run& { return map.unrepaired_unsmoothed; },
      [](const MapRuns& map) -> const Run& { return map.unrepaired_no_contact; },
      [](const MapRuns& map) -> const Run& { return map.runs[kUnsmoothed]; }, no_contact,
      by_default};
  for (const MapSet& set : sets) {
    std::printf("| %s | %zu |", set.label.c_str(), set.maps.size());
    for (const RunOf& run_of : columns) {
      std::vector<double> times;
      for (const MapRuns& map : set.maps) times.push_back(run_of(map).traversal_time_s);
      std::printf(" %.2f |", median(times));
    }
    std::printf(" %.1f | %.1f |\n", turnsSmoothedPercent(set.maps, no_contact),
                turnsSmoothedPercent(set.maps, by_default));
  }
}

/// One map's figures per strategy, on stderr: reachable coverage, traversal time ratio to
/// the unsmoothed trajectory, wall time.
void printMap(const std::string& family, std::uint64_t seed, const MapRuns& map) {
  std::fprintf(stderr, "%s seed %llu:", family.c_str(), static_cast<unsigned long long>(seed));
  for (int s = 0; s < kStrategies; ++s) {
    const Run& run = map.runs[s];
    std::fprintf(stderr, " %s %.3f %% %.3f %.2f s;", strategyName(Strategy(s)).c_str(),
                 run.reachable_percent,
                 run.traversal_time_s / map.runs[kUnsmoothed].traversal_time_s, run.wall_s);
  }
  std::fprintf(stderr, "\n");
}

/// Table 1's row of one strategy over a batch of maps.
void printStrategyRow(const std::string& label, Strategy strategy,
                      const std::vector<MapRuns>& maps) {
  std::vector<double> reachable;
  std::vector<double> ratios;
  double worst_drop = 0.0;
  double wall = 0.0;
  double unsmoothed_wall = 0.0;
  int under_bar = 0;
  int over_wall = 0;
  for (const MapRuns& map : maps) {
    const Run& run = map.runs[strategy];
    const Run& reference = map.runs[kUnsmoothed];
    reachable.push_back(run.reachable_percent);
    ratios.push_back(run.traversal_time_s / reference.traversal_time_s);
    worst_drop = std::max(worst_drop, reference.reachable_percent - run.reachable_percent);
    under_bar += run.reachable_percent < kCoverageBarPercent ? 1 : 0;
    wall += run.wall_s;
    unsmoothed_wall += reference.wall_s;
    over_wall += run.wall_s > kWallFactor * reference.wall_s + kWallSlack ? 1 : 0;
  }
  std::printf("| %s | %s | %zu | %.3f | %.3f | %d | %.3f | %.3f | %.2f | %.3f | %d |\n",
              label.c_str(), strategyName(strategy).c_str(), maps.size(), median(reachable),
              *std::min_element(reachable.begin(), reachable.end()), under_bar, worst_drop,
              median(ratios), wall, wall / unsmoothed_wall, over_wall);
}

/// Turns smoothed and coverage over a set of lake maps, per strategy (table 3).
/// The rows of table 3 for `maps`; the default's share of turns smoothed (%).
double printLakeRows(const std::string& label, const std::vector<MapRuns>& maps) {
  double default_share = 100.0;
  for (int s = 0; s < kStrategies; ++s) {
    int smoothed = 0;
    int total = 0;
    double worst = 100.0;
    for (const MapRuns& map : maps) {
      smoothed += map.runs[s].turns_smoothed;
      total += map.runs[s].turns_total;
      worst = std::min(worst, map.runs[s].reachable_percent);
    }
    const double share = total > 0 ? 100.0 * smoothed / total : 100.0;
    if (s == kDefault) default_share = share;
    std::printf("| %s | %s | %d | %d | %.1f | %.3f |\n", label.c_str(),
                strategyName(Strategy(s)).c_str(), smoothed, total, share, worst);
  }
  return default_share;
}

int run(const Options& options) {
  // Each run writes its files as `coverage_tool plan` does, into one scratch directory.
  std::string scratch =
      (std::filesystem::temp_directory_path() / ("strategy_benchmark." + std::string(6, 'X')))
          .string();  // mkdtemp's template
  if (mkdtemp(scratch.data()) == nullptr) {
    std::fprintf(stderr, "strategy_benchmark: cannot create a directory in %s\n",
                 std::filesystem::temp_directory_path().c_str());
    return 2;
  }
  const ScratchDirectory out_dir{scratch};
  // Table 1, family by family; the sets of maps for tables 2 and 4.
  std::vector<MapSet> sets;
  std::printf(
      "| family, maps | strategy | maps | reachable coverage %%, median | reachable coverage %%, "
      "worst | maps under 99.9 %% | largest drop below unsmoothed, points | traversal time "
      "ratio to unsmoothed, median | summed wall s (timing) | summed wall ratio to unsmoothed "
      "(timing) | maps over 1.3 x unsmoothed + 0.5 s (timing) |\n"
      "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  int failed = 0;
  for (const testing::MapFamily family : options.families) {
    const testing::HardMapGenerator generator(family);
    const std::string name = testing::HardMapGenerator::name(family);
    std::uint64_t seed = 0;
    int done = 0;
    int refused = 0;
    std::vector<MapRuns> all;
    // Maps whose goal the planner refuses (beyond a narrow gap) are named in the label,
    // so that the "maps" column's count matches it.
    const auto refusals = [](int count) {
      return count == 0 ? std::string() : ", " + std::to_string(count) + " refused";
    };
    // The rows of a set of maps: one per strategy.
    const auto report = [&](const std::string& label, const std::vector<MapRuns>& maps) {
      for (int s = 0; s < kStrategies; ++s) printStrategyRow(label, Strategy(s), maps);
      sets.push_back({label, maps});
    };
    for (const int batch : options.batches) {
      std::vector<MapRuns> maps;
      const int refused_before = refused;
      for (int i = 0; i < batch; ++i, ++seed) {
        try {
          maps.push_back(runMap(generator.generate(seed).mission, out_dir.path));
          if (options.per_map) printMap(name, seed, maps.back());
        } catch (const UnreachableGoalError& error) {
          std::fprintf(stderr, "refused %s seed %llu: %s\n", name.c_str(),
                       static_cast<unsigned long long>(seed), error.what());
          ++refused;
        } catch (const std::exception& error) {
          std::fprintf(stderr, "FAIL %s seed %llu: %s\n", name.c_str(),
                       static_cast<unsigned long long>(seed), error.what());
          ++failed;
        }
      }
      if (maps.empty()) continue;
      if (done == 0) {
        report(name + ", maps " + std::to_string(done + 1) + "-" + std::to_string(done + batch) +
                   refusals(refused - refused_before),
               maps);
      }
      done += batch;
      all.insert(all.end(), maps.begin(), maps.end());
      std::fprintf(stderr, "progress: %s, %d maps\n", name.c_str(), done);
      std::fflush(stdout);
    }
    // Several batches: the family's figures over all of them too.
    if (options.batches.size() > 1 && !all.empty()) {
      report(name + ", all " + std::to_string(done) + " maps" + refusals(refused), all);
    }
  }

  printBaselineTable(sets);

  std::printf(
      "\n| maps | strategy | turns smoothed | turns | turns smoothed %% | reachable coverage %%, "
      "worst |\n|---|---|---:|---:|---:|---:|\n");
  const Mission lake =
      MissionFileReader().read(std::string(KC_SOURCE_DIR) + "/config/missions/lake_30x30.yaml");
  std::vector<MapSet> lake_sets = {{"lake_30x30", {runMap(lake, out_dir.path)}}};
  printLakeRows(lake_sets.back().label, lake_sets.back().maps);
  if (options.lakes > 0) {
    std::vector<MapRuns> lakes;
    for (int seed = 1; seed <= options.lakes; ++seed) {
      lakes.push_back(runMap(testing::LakeMapGenerator().generate(seed), out_dir.path));
    }
    lake_sets.push_back({"lakes 1-" + std::to_string(options.lakes), lakes});
    const double share = printLakeRows(lake_sets.back().label, lakes);
    std::printf(
        "\nbar: the default smooths at least %.0f %% of the lake maps' turns: %.1f %%, %s\n",
        kLakeTurnsBarPercent, share, share >= kLakeTurnsBarPercent ? "met" : "MISSED");
  }
  printLossTable(sets);
  sets.insert(sets.end(), lake_sets.begin(), lake_sets.end());
  printClearanceTable(sets);
  printTimePartsTable(sets);
  return failed == 0 ? 0 : 1;
}

}  // namespace
}  // namespace kinematic_coverage::core

int main(int argc, char** argv) {
  return kinematic_coverage::core::run(kinematic_coverage::core::parseOptions(argc, argv));
}
