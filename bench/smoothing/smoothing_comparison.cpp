// Smoothing strategies side by side: Algorithm 1 (`local`), the global programme
// (`global`) and the global programme with coverage preservation, on the shipped lake
// missions, the peer planner's example polygons and seeded random maps (the soak test's
// sizes, 0 to 15 holes). Each map is planned once; each strategy turns the same waypoints
// into a trajectory with the map's parameters, and the unsmoothed trajectory is the
// reference for coverage. Prints per map: turns smoothed, traversal time, trajectory length,
// coverage loss; then the random maps' totals and the maps where global is slower than local
// (exit status 1 if there is one).
//
//   smoothing_comparison [--random-maps 50] [--peer-dir DIR] [--per-seed] [--only MAP]
//
// --only MAP: only the named maps whose name contains MAP, no random maps.

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
#include "polygon_coverage_ros_bridge/base/elapsed_seconds.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "test/support/random_missions.h"

namespace kinematic_coverage::core {
namespace {

/// What the command line asks for.
struct ComparisonOptions {
  int random_maps = 50;
  std::string peer_dir = KC_PEER_POLYGONS_DIR;
  bool per_seed = false;
  std::string only;  ///< non-empty: only the named maps containing this
};

/// A strategy's figures on one map.
struct StrategyFigures {
  int turns_smoothed = 0;
  int turns_total = 0;
  double traversal_time_s = 0.0;
  double trajectory_length_m = 0.0;
  double coverage_loss_percent = 0.0;
};

/// The strategies compared, in column order; the last is the unsmoothed reference.
constexpr int kStrategies = 4;
const char* const kStrategyNames[kStrategies] = {"local", "global", "global+coverage",
                                                 "unsmoothed"};

PlannerParameters withStrategy(PlannerParameters parameters, int strategy) {
  parameters.smoothing = strategy != 3;
  parameters.smoothing_strategy = strategy == 0 ? "local" : "global";
  parameters.coverage_preserving = strategy == 2;
  return parameters;
}

/// Plans `mission` and measures every strategy on its waypoints.
std::vector<StrategyFigures> compare(const Mission& mission) {
  const PlannedMission planned = planMission(mission);
  std::vector<StrategyFigures> figures;
  for (int strategy = 0; strategy < kStrategies; ++strategy) {
    const PlannerParameters parameters = withStrategy(mission.parameters, strategy);
    const TrajectoryPipeline pipeline(parameters, planned.plan.exact_offset_parts);
    const GeneratedTrajectory trajectory =
        pipeline.trajectory(planned.plan.waypoints, planned.free_area);
    std::vector<Pose2> poses;
    poses.reserve(trajectory.poses.size());
    for (const TrajectoryPose& pose : trajectory.poses) poses.push_back(pose.pose());
    const TrajectoryCoverage coverage = pipeline.measure(planned.free_area, poses, std::nullopt);
    figures.push_back({trajectory.statistics.turns_smoothed, trajectory.statistics.turns_total,
                       trajectory.traversal_time_s, trajectory.trajectory_length_m,
                       coverage.report.coverage_loss_percent});
  }
  return figures;
}

void printHeader() {
  std::printf(
      "| map | strategy | turns smoothed | traversal time s | length m | coverage loss %% |\n");
  std::printf("|---|---|---:|---:|---:|---:|\n");
}

void printRows(const std::string& map, const std::vector<StrategyFigures>& figures) {
  for (int strategy = 0; strategy < kStrategies; ++strategy) {
    const StrategyFigures& f = figures[strategy];
    std::printf("| %s | %s | %d / %d | %.1f | %.1f | %.3f |\n", map.c_str(),
                kStrategyNames[strategy], f.turns_smoothed, f.turns_total, f.traversal_time_s,
                f.trajectory_length_m, f.coverage_loss_percent);
  }
}

ComparisonOptions parseOptions(int argc, char** argv) {
  const auto usage = [] {
    std::fprintf(stderr,
                 "usage: smoothing_comparison [--random-maps 50] [--peer-dir DIR] [--per-seed]\n"
                 "                            [--only MAP]\n");
    std::exit(2);
  };
  ComparisonOptions options;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--per-seed") {
      options.per_seed = true;
    } else if (flag == "--random-maps" && i + 1 < argc) {
      options.random_maps = std::atoi(argv[++i]);
      if (options.random_maps < 0) usage();
    } else if (flag == "--only" && i + 1 < argc) {
      options.only = argv[++i];
      options.random_maps = 0;
    } else if (flag == "--peer-dir" && i + 1 < argc) {
      options.peer_dir = argv[++i];
    } else {
      usage();
    }
  }
  return options;
}

int run(const ComparisonOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  std::vector<std::string> slower;  // maps where global is slower than local
  const auto check = [&slower](const std::string& map, const std::vector<StrategyFigures>& f) {
    if (f[1].traversal_time_s > f[0].traversal_time_s + 1e-9) slower.push_back(map);
  };

  std::vector<std::pair<std::string, std::string>> files;
  for (const char* name : {"lake_30x30", "lake_7_5", "parallelogram_60"}) {
    files.push_back({name, std::string(KC_SOURCE_DIR) + "/config/missions/" + name + ".yaml"});
  }
  std::vector<std::string> peer;
  for (const auto& entry : std::filesystem::directory_iterator(options.peer_dir)) {
    if (entry.path().extension() == ".yaml") peer.push_back(entry.path().string());
  }
  std::sort(peer.begin(), peer.end());
  for (const std::string& path : peer) {
    files.push_back({"pcp " + std::filesystem::path(path).stem().string(), path});
  }

  printHeader();
  for (const auto& [name, path] : files) {
    if (name.find(options.only) == std::string::npos) continue;
    const std::vector<StrategyFigures> figures = compare(MissionFileReader().read(path));
    printRows(name, figures);
    check(name, figures);
  }

  // Random maps: totals over the maps that plan (a start or goal the map makes
  // impossible is refused with a precise error and skipped).
  std::vector<StrategyFigures> totals(kStrategies);
  int planned_maps = 0;
  int refused_maps = 0;
  for (int seed = 0; seed < options.random_maps; ++seed) {
    const std::string name = "random seed " + std::to_string(seed);
    std::vector<StrategyFigures> figures;
    try {
      figures = compare(testing::randomMission(static_cast<std::uint64_t>(seed), 15).mission);
    } catch (const InvalidInputError& error) {
      ++refused_maps;
      std::fprintf(stderr, "%s refused: %s\n", name.c_str(), error.what());
      continue;
    }
    ++planned_maps;
    check(name, figures);
    if (options.per_seed) printRows(name, figures);
    for (int strategy = 0; strategy < kStrategies; ++strategy) {
      StrategyFigures& total = totals[strategy];
      total.turns_smoothed += figures[strategy].turns_smoothed;
      total.turns_total += figures[strategy].turns_total;
      total.traversal_time_s += figures[strategy].traversal_time_s;
      total.trajectory_length_m += figures[strategy].trajectory_length_m;
      total.coverage_loss_percent += figures[strategy].coverage_loss_percent;
    }
    if ((seed + 1) % 10 == 0) {
      std::fprintf(stderr, "progress: %d of %d random maps\n", seed + 1, options.random_maps);
    }
  }
  if (planned_maps > 0) {
    for (StrategyFigures& total : totals) total.coverage_loss_percent /= planned_maps;
    printRows(std::to_string(planned_maps) + " random maps (sum; mean loss)", totals);
  }
  const double seconds = secondsSince(started);
  std::printf("\n%zu named maps, %d random maps planned, %d refused; %.1f s\n", files.size(),
              planned_maps, refused_maps, seconds);
  if (slower.empty()) {
    std::printf("global is never slower than local\n");
    return 0;
  }
  for (const std::string& map : slower)
    std::printf("global SLOWER than local on %s\n", map.c_str());
  return 1;
}

}  // namespace
}  // namespace kinematic_coverage::core

int main(int argc, char** argv) {
  try {
    return kinematic_coverage::core::run(kinematic_coverage::core::parseOptions(argc, argv));
  } catch (const std::exception& error) {
    std::fprintf(stderr, "smoothing_comparison: %s\n", error.what());
    return 1;
  }
}
