// Soak test: plans and smooths seeded random maps with 0 to 15 holes (hulls 50 to 200 m
// across, footprints 2 to 12.9 m wide), and checks on every seed: no exception but a
// precise InvalidInputError for a start or goal the map makes impossible, no collision of
// the smoothed trajectory, which keeps the wall distance (within kClearanceTolerance) or
// comes no nearer than the unsmoothed trajectory (which passes gaps narrower than two wall
// distances), and at least 99 % coverage of the reachable area by the waypoint path.
// Prints a progress line every 100 seeds, each failure with its seed, and a table with a
// row per seed range (and their total when there are several): the outcomes and the
// planning-time distribution. Exit status 1 when any seed failed.
// --trajectory-coverage also measures the smoothed trajectory's reachable coverage and
// adds its distribution (smoothing cuts corners by design, so it is reported, not checked).
//
// Usage: soak_test --seeds FIRST:LAST[,FIRST:LAST...] [--holes-max 15] [--trajectory-coverage]

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "coverage_system/mission/trajectory_pipeline.h"
#include "coverage_system/parameters/stage_options.h"
#include "coverage_system/planner/coverage_planner.h"
#include "polygon_coverage_ros_bridge/base/elapsed_seconds.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"
#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"
#include "test/support/random_missions.h"
#include "trajectory_generation_tools/coverage/coverage_evaluator.h"

namespace kinematic_coverage::core {
namespace {

/// Least share of the reachable area the waypoint path must cover.
constexpr double kMinCoveragePercent = 99.0;

/// The seed ranges and map shape asked for on the command line.
struct SoakOptions {
  std::vector<std::pair<std::uint64_t, std::uint64_t>> seed_ranges;  ///< first, last
  int holes_max = 15;
  bool trajectory_coverage = false;
};

/// The smoothed trajectory's reachable coverage (%) of one seed.
struct TrajectoryCoverageSample {
  double percent = 0.0;
  std::uint64_t seed = 0;
};

/// What became of one seed.
enum class SoakOutcome { kPassed, kRejected, kFailed };

/// Parses `--seeds FIRST:LAST[,...] [--holes-max N] [--trajectory-coverage]`; exits with a
/// usage line when malformed.
SoakOptions parseOptions(int argc, char** argv) {
  const auto usage = [] {
    std::cerr << "usage: soak_test --seeds FIRST:LAST[,FIRST:LAST...] [--holes-max 15] "
                 "[--trajectory-coverage]\n";
    std::exit(2);
  };
  SoakOptions options;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--trajectory-coverage") {
      options.trajectory_coverage = true;
      continue;
    }
    if (i + 1 >= argc) usage();
    const std::string value = argv[++i];
    if (flag == "--seeds") {
      std::istringstream ranges(value);
      std::string range;
      while (std::getline(ranges, range, ',')) {
        const std::size_t colon = range.find(':');
        if (colon == std::string::npos) usage();
        const std::uint64_t first = std::stoull(range.substr(0, colon));
        const std::uint64_t last = std::stoull(range.substr(colon + 1));
        if (first > last) usage();
        options.seed_ranges.emplace_back(first, last);
      }
    } else if (flag == "--holes-max") {
      options.holes_max = std::stoi(value);
      if (options.holes_max < 0) usage();
    } else {
      usage();
    }
  }
  if (options.seed_ranges.empty()) usage();
  return options;
}

/// True for the planner's precise rejections of a start or goal the map makes impossible
/// (inside a hole, or joined to the offset area only through a hole); a goal that a robot
/// keeping the gap clearance cannot reach is an UnreachableGoalError.
bool isPreciseRejection(const std::string& message) {
  return message.find("crosses a hole") != std::string::npos ||
         message.find("lies inside hole") != std::string::npos;
}

/// Plans, smooths and checks one seed; prints a line for a failure. Adds the planning
/// time of a plan that was made to `planning_times_s`, and with `trajectory_coverage` the
/// smoothed trajectory's reachable coverage to that vector.
SoakOutcome runSeed(std::uint64_t seed, int holes_max, std::vector<double>& planning_times_s,
                    std::vector<TrajectoryCoverageSample>* trajectory_coverage) {
  const testing::RandomMission random = testing::randomMission(seed, holes_max);
  const Mission& mission = random.mission;
  std::ostringstream context;
  context << "seed " << seed << " (size " << std::fixed << std::setprecision(1) << random.size_m
          << " m, holes " << mission.polygon.holes.size() << ", footprint "
          << random.footprint_width_m << " m)";
  const auto fail = [&context](const std::string& why) {
    std::cout << "FAIL " << context.str() << ": " << why << std::endl;
    return SoakOutcome::kFailed;
  };
  try {
    const auto started = std::chrono::steady_clock::now();
    const CoveragePlan plan =
        CoveragePlanner(mission.parameters).plan(mission.polygon, mission.start, mission.goal);
    planning_times_s.push_back(secondsSince(started));
    const TrajectoryPipeline pipeline(mission.parameters, plan.exact_offset_parts);
    const GeneratedTrajectory trajectory = pipeline.trajectory(plan.waypoints, mission.polygon);
    if (!(trajectory.min_obstacle_clearance_m > 0.0)) {
      return fail("collision: min_obstacle_clearance_m " +
                  std::to_string(trajectory.min_obstacle_clearance_m));
    }
    // The smoothed trajectory keeps the wall distance, or comes no nearer than the
    // unsmoothed one (which passes gaps narrower than two wall distances).
    const std::optional<GeneratedTrajectory> sharp =
        pipeline.sharpTrajectory(plan.waypoints, mission.polygon);
    const double sharp_clearance = (sharp ? *sharp : trajectory).min_obstacle_clearance_m;
    const double least = std::min(mission.parameters.wall_distance, sharp_clearance);
    if (!keepsClearance(trajectory.min_obstacle_clearance_m, least)) {
      return fail("clearance: min_obstacle_clearance_m " +
                  std::to_string(trajectory.min_obstacle_clearance_m) + ", less than " +
                  std::to_string(least));
    }
    const std::vector<PolygonWithHoles> reachable =
        exactOffsetParts(mission.polygon, mission.parameters.wall_distance, plan.offset_parts);
    const double covered = waypointPathReachableCoveragePercent(
        mission.polygon, reachable, sensorOf(mission.parameters), plan.waypoints,
        RasterResolution{0.0, 1e-3, 1'000'000});
    if (!(covered >= kMinCoveragePercent)) {
      return fail("reachable coverage " + std::to_string(covered) + " %");
    }
    if (trajectory_coverage) {
      std::vector<Pose2> poses;
      poses.reserve(trajectory.poses.size());
      for (const TrajectoryPose& pose : trajectory.poses) poses.push_back(pose.pose());
      const CoverageEvaluator evaluator(mission.polygon, reachable, sensorOf(mission.parameters),
                                        RasterResolution{0.0, 1e-3, 1'000'000});
      trajectory_coverage->push_back(
          {evaluator.report(evaluator.seeTrajectory(poses)).reachable_coverage_percent, seed});
    }
    return SoakOutcome::kPassed;
  } catch (const UnreachableGoalError&) {
    return SoakOutcome::kRejected;
  } catch (const InvalidInputError& error) {
    if (isPreciseRejection(error.what())) return SoakOutcome::kRejected;
    return fail(std::string("InvalidInputError: ") + error.what());
  } catch (const std::exception& error) {
    return fail(std::string("exception: ") + error.what());
  }
}

/// The q-quantile (0..1) of sorted `values`, nearest rank.
double quantile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return 0.0;
  const auto rank = static_cast<std::size_t>(std::ceil(q * sorted.size()));
  return sorted[std::min(sorted.size() - 1, rank == 0 ? 0 : rank - 1)];
}

/// The outcomes of a range of seeds.
struct SoakTally {
  int passed = 0;
  int rejected = 0;
  int failed = 0;
  std::vector<double> planning_times_s;
  std::vector<TrajectoryCoverageSample> trajectory_coverage;

  void add(const SoakTally& other) {
    passed += other.passed;
    rejected += other.rejected;
    failed += other.failed;
    planning_times_s.insert(planning_times_s.end(), other.planning_times_s.begin(),
                            other.planning_times_s.end());
    trajectory_coverage.insert(trajectory_coverage.end(), other.trajectory_coverage.begin(),
                               other.trajectory_coverage.end());
  }
};

/// Runs seeds `first` to `last`, with a progress line every 100 seeds.
SoakTally runRange(std::uint64_t first, std::uint64_t last, const SoakOptions& options) {
  SoakTally tally;
  std::uint64_t done = 0;
  for (std::uint64_t seed = first;; ++seed) {
    switch (runSeed(seed, options.holes_max, tally.planning_times_s,
                    options.trajectory_coverage ? &tally.trajectory_coverage : nullptr)) {
      case SoakOutcome::kPassed:
        ++tally.passed;
        break;
      case SoakOutcome::kRejected:
        ++tally.rejected;
        break;
      case SoakOutcome::kFailed:
        ++tally.failed;
        break;
    }
    if (++done % 100 == 0) {
      std::cerr << "progress: " << done << " seeds (up to " << seed << "), passed " << tally.passed
                << ", rejected " << tally.rejected << ", failed " << tally.failed << std::endl;
    }
    if (seed == last) break;
  }
  return tally;
}

/// One table row: outcomes, the smoothed trajectories' reachable coverage (least, with its
/// seed, 1st percentile, median; "-" without --trajectory-coverage) and planning times.
void printRow(const std::string& seeds, SoakTally tally) {
  std::sort(tally.planning_times_s.begin(), tally.planning_times_s.end());
  std::cout << std::fixed << "| " << seeds << " | " << tally.passed << " | " << tally.rejected
            << " | " << tally.failed << " | ";
  if (tally.trajectory_coverage.empty()) {
    std::cout << "- | - | - | ";
  } else {
    std::sort(tally.trajectory_coverage.begin(), tally.trajectory_coverage.end(),
              [](const auto& a, const auto& b) { return a.percent < b.percent; });
    std::vector<double> percents;
    for (const TrajectoryCoverageSample& sample : tally.trajectory_coverage) {
      percents.push_back(sample.percent);
    }
    std::cout << std::setprecision(3) << percents.front() << " (seed "
              << tally.trajectory_coverage.front().seed << ") | " << quantile(percents, 0.01)
              << " | " << quantile(percents, 0.5) << " | ";
  }
  const std::vector<double>& times = tally.planning_times_s;
  std::cout << std::setprecision(3) << quantile(times, 0.5) << " | " << quantile(times, 0.99)
            << " | " << (times.empty() ? 0.0 : times.back()) << " |" << std::endl;
}

}  // namespace
}  // namespace kinematic_coverage::core

int main(int argc, char** argv) {
  using namespace kinematic_coverage::core;
  const SoakOptions options = parseOptions(argc, argv);
  std::vector<std::pair<std::string, SoakTally>> rows;
  SoakTally total;
  for (const auto& [first, last] : options.seed_ranges) {
    rows.emplace_back(std::to_string(first) + ":" + std::to_string(last),
                      runRange(first, last, options));
    total.add(rows.back().second);
  }
  std::cout << "holes-max " << options.holes_max << "\n"
            << "| seeds | passed | rejected | failed | smoothed reachable coverage, least % | "
               "1st percentile % | median % | median plan s (timing) | p99 plan s (timing) | "
               "max plan s (timing) |\n|---|---:|---:|---:|---|---:|---:|---:|---:|---:|\n";
  for (const auto& [seeds, tally] : rows) printRow(seeds, tally);
  if (rows.size() > 1) printRow("total", total);
  return total.failed == 0 ? 0 : 1;
}
