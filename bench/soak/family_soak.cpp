// Family soak: plans HardMapGenerator's maps (test/support/hard_map_generator.h: combs,
// spirals, rooms joined by a corridor, noisy shorelines with islands, touching holes and
// the star-shaped family) as `coverage_tool plan` does (validate, clean, plan) and turns
// each plan into a trajectory with default settings and with smoothing off. Every map must
// plan (an InvalidInputError is a map the package wrongly calls invalid, any other error
// an internal one; an UnreachableGoalError, a goal that a robot keeping gap_clearance
// cannot reach, is counted apart as refused), and for both trajectories:
//  - every leg from first_inside to last_inside lies in the route area (the offset free
//    area's parts joined through their gaps) or keeps the wall distance (the repair's
//    excursions toward the exact offset's boundary), the legs to the start and goal in the
//    free area;
//  - every pose lies in the free area and the trajectory keeps a clearance above 0; the
//    default one keeps the wall distance (within kClearanceTolerance) or comes no nearer
//    than the unsmoothed one (which passes gaps narrower than two wall distances);
//  - consecutive poses are at most the sampling distance apart (continuity), and the
//    curvature is at most 1 / r;
//  - on maps of at most --oracle-max-vertices vertices (cleaned), the coverage that
//    metrics.json reports (coverage_percent) equals the exact polygon oracle's
//    (test/coverage/exact_coverage_oracle.h) within 0.1 % of the free area. The unseen
//    reachable area is compared too, with the oracle's reachable area grown from the
//    planner's offset free area, and its largest difference printed, not checked: the
//    raster grows the offset free area up to half a cell too far, which long offset
//    boundaries (spirals, combs) turn into up to 0.5 % of the free area.
// Each family runs in a child process, so that its peak resident memory is its own. Prints
// each failure with its family and seed, a progress line every 20 maps, and a table with a
// row per family, with the default trajectories' least closest approach / wall_distance,
// the maps nearer than wall_distance, the share of turns smoothed and the median traversal
// time ratio to the unsmoothed trajectories. Exit status 1 when any map failed.
//
// Usage: family_soak --maps N[,N...] [--first-seed S] [--families comb,spiral,...]
//                    [--max-vertices V] [--oracle-max-vertices 200]
// Seeds are taken from S on; maps of more than V vertices are passed over (not counted).
// Each N is a batch of maps with its own table row ("comb, maps 1-5", "comb, maps 6-200"),
// so that a short run prints the first rows of a long one.

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iomanip>
#include <iostream>
#include <limits>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "coverage_system/mission/mission_planner.h"
#include "coverage_system/mission/trajectory_coverage.h"
#include "coverage_system/mission/trajectory_pipeline.h"
#include "polygon_coverage_ros_bridge/base/elapsed_seconds.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"
#include "test/coverage/exact_coverage_oracle.h"
#include "test/support/hard_map_generator.h"
#include "trajectory_generation_tools/smoothing/boundary_edge_index.h"

namespace kinematic_coverage::core {
namespace {

/// Most difference, in percent of the free area, between the reported and the exact
/// coverage figures.
constexpr double kOracleAgreementPercent = 0.1;
/// Legs and poses may leave their areas by this much (rounding), relative to the map.
constexpr double kRelativeTolerance = 1e-9;
/// Slack on the sampling distance and the curvature bound (rounding).
constexpr double kSamplingSlack = 1e-6;
constexpr double kCurvatureSlack = 1e-6;
/// Seeds passed over for their size in a row before a family is given up (its maps are
/// larger).
constexpr std::uint64_t kMaxPassedOver = 10'000;

struct Options {
  std::vector<int> batches;  ///< maps per table row, in order
  std::uint64_t first_seed = 0;
  std::vector<testing::MapFamily> families = testing::HardMapGenerator::families();
  std::size_t max_vertices = std::numeric_limits<std::size_t>::max();
  std::size_t oracle_max_vertices = 200;
};

[[noreturn]] void usage() {
  std::cerr << "usage: family_soak --maps N[,N...] [--first-seed S] [--families comb,spiral,...] "
               "[--max-vertices V] [--oracle-max-vertices 200]\n";
  std::exit(2);
}

Options parseOptions(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (i + 1 >= argc) usage();
    const std::string value = argv[++i];
    if (flag == "--maps") {
      std::istringstream sizes(value);
      std::string size;
      while (std::getline(sizes, size, ',')) {
        options.batches.push_back(std::stoi(size));
        if (options.batches.back() <= 0) usage();
      }
    } else if (flag == "--first-seed") {
      options.first_seed = std::stoull(value);
    } else if (flag == "--families") {
      const auto named = testing::HardMapGenerator::fromNames(value);
      if (!named) usage();
      options.families = *named;
    } else if (flag == "--max-vertices") {
      options.max_vertices = std::stoull(value);
    } else if (flag == "--oracle-max-vertices") {
      options.oracle_max_vertices = std::stoull(value);
    } else {
      usage();
    }
  }
  if (options.batches.empty() || options.families.empty()) usage();
  return options;
}

std::size_t vertexCount(const PolygonWithHoles& polygon) {
  std::size_t count = polygon.hull.size();
  for (const Ring& hole : polygon.holes) count += hole.size();
  return count;
}

/// What the check of one trajectory measured.
struct TrajectoryFigures {
  double clearance_m = 0.0;
  double traversal_time_s = 0.0;
  int turns_smoothed = 0;
  int turns_total = 0;
};

/// The default trajectory's figures beside what they are compared with.
struct DefaultTrajectory {
  TrajectoryFigures figures;
  double wall_distance = 0.0;
  double unsmoothed_time_s = 0.0;
};

/// What one map showed.
struct MapResult {
  bool failed = false;
  /// Refused precisely: the goal lies where a robot keeping the gap clearance cannot reach
  /// from the start (docs/REFERENCE.md, Parts).
  bool refused = false;
  bool split = false;       ///< planned over several parts of the offset free area
  bool oracle = false;      ///< small enough for the oracle
  int oracle_measured = 0;  ///< trajectories the oracle measured (of two)
  /// Largest |reported - exact| of coverage_percent and of the unseen reachable area, both
  /// in % of the free area.
  double coverage_difference_percent = 0.0;
  double unseen_difference_percent = 0.0;
  double planning_time_s = 0.0;
  /// For maps planned and checked with a wall distance.
  std::optional<DefaultTrajectory> default_trajectory;
};

/// The failures of one trajectory, one line each (none when it passes). A trajectory
/// touches no wall, and comes no nearer than `least_clearance_m` (within
/// kClearanceTolerance); its clearance, time and turns go to `figures`.
std::vector<std::string> checkTrajectory(const PolygonWithHoles& free_area,
                                         const CoveragePlan& plan,
                                         const PlannerParameters& parameters, bool with_oracle,
                                         double tolerance, double least_clearance_m,
                                         const std::string& label, MapResult* result,
                                         TrajectoryFigures* figures) {
  std::vector<std::string> failures;
  const TrajectoryPipeline pipeline(parameters, plan.exact_offset_parts);
  const GeneratedTrajectory trajectory = pipeline.trajectory(plan.waypoints, free_area);
  figures->clearance_m = trajectory.min_obstacle_clearance_m;
  figures->traversal_time_s = trajectory.traversal_time_s;
  figures->turns_smoothed = trajectory.statistics.turns_smoothed;
  figures->turns_total = trajectory.statistics.turns_total;
  if (!(trajectory.min_obstacle_clearance_m > 0.0)) {
    failures.push_back("collision: min_obstacle_clearance_m " +
                       std::to_string(trajectory.min_obstacle_clearance_m));
  } else if (!keepsClearance(trajectory.min_obstacle_clearance_m, least_clearance_m)) {
    failures.push_back("clearance: min_obstacle_clearance_m " +
                       std::to_string(trajectory.min_obstacle_clearance_m) + ", less than " +
                       std::to_string(least_clearance_m));
  }
  const double spacing =
      std::max(parameters.segment_sampling_distance, parameters.arc_sampling_distance);
  std::vector<Pose2> poses;
  for (std::size_t i = 0; i < trajectory.poses.size(); ++i) {
    const TrajectoryPose& pose = trajectory.poses[i];
    poses.push_back({pose.x, pose.y, wrapAngle(pose.yaw)});
    if (!contains(free_area, poses.back().position(), tolerance)) {
      failures.push_back("pose " + std::to_string(i) + " outside the free area");
      break;
    }
    if (i > 0 &&
        (poses[i].position() - poses[i - 1].position()).norm() > spacing + kSamplingSlack) {
      failures.push_back("poses " + std::to_string(i - 1) + " and " + std::to_string(i) +
                         " farther apart than the sampling distance");
      break;
    }
  }
  const double radius = parameters.min_turning_radius > 0.0 ? parameters.min_turning_radius
                                                            : parameters.turning_radius;
  if (parameters.smoothing && trajectory.max_curvature > 1.0 / radius + kCurvatureSlack) {
    failures.push_back("curvature " + std::to_string(trajectory.max_curvature) + " above 1/r");
  }
  if (!failures.empty() || !with_oracle) return failures;
  const TrajectoryCoverage reported = pipeline.measure(free_area, poses, std::nullopt);
  // The oracle measures the reachable area that the report does: the exact offset around
  // the planner's mitred parts.
  testing::ExactCoverage exact;
  try {
    const testing::ExactCoverageOracle oracle(
        free_area, exactOffsetParts(free_area, parameters.wall_distance, plan.offset_parts),
        testing::oracleFootprint(parameters));
    exact = oracle.measure(poses);
  } catch (const std::bad_alloc&) {
    // The oracle's limit, not the package's: the map is not counted checked.
    std::cerr << "note: " << label << ": the oracle ran out of memory on " << poses.size()
              << " poses; not counted as checked" << std::endl;
    return failures;
  }
  ++result->oracle_measured;
  const double free_m2 = exact.free_area_m2;
  const double coverage = std::abs(reported.report.coverage_percent - exact.coverage_percent);
  const double unseen =
      std::abs(100.0 * reported.report.unseen_reachable_area_m2 / free_m2 -
               100.0 * (exact.reachable_area_m2 - exact.seen_reachable_area_m2) / free_m2);
  result->coverage_difference_percent = std::max(result->coverage_difference_percent, coverage);
  result->unseen_difference_percent = std::max(result->unseen_difference_percent, unseen);
  if (coverage > kOracleAgreementPercent) {
    std::ostringstream line;
    line << "coverage " << reported.report.coverage_percent << " % against the oracle's "
         << exact.coverage_percent << " %";
    failures.push_back(line.str());
  }
  return failures;
}

/// Plans and checks one map, printing a line per failure.
MapResult runMap(const testing::HardMap& map, const Options& options) {
  MapResult result;
  const std::string family = testing::HardMapGenerator::name(map.family);
  const auto fail = [&](const std::string& why) {
    std::cout << "FAIL " << family << " seed " << map.seed << ": " << why << std::endl;
    result.failed = true;
  };
  try {
    const auto started = std::chrono::steady_clock::now();
    const PlannedMission planned = planMission(map.mission);
    result.planning_time_s = secondsSince(started);
    const CoveragePlan& plan = planned.plan;
    result.split = plan.offset_parts.size() > 1;
    double scale = 1.0;
    for (const Point2& p : planned.free_area.hull) scale = std::max(scale, p.cwiseAbs().maxCoeff());
    const double tolerance = kRelativeTolerance * scale;
    const BoundaryEdgeIndex walls(planned.free_area, map.mission.parameters.wall_distance);
    for (std::size_t i = 0; i + 1 < plan.waypoints.size(); ++i) {
      const Point2 a = plan.waypoints[i].position();
      const Point2 b = plan.waypoints[i + 1].position();
      const bool inside = i >= plan.first_inside && i + 1 <= plan.last_inside;
      // A leg out of the route area is a repair's excursion toward the exact offset's
      // boundary: it must keep the wall distance.
      const bool excursion = inside && segmentInside(planned.free_area, a, b, 1e3 * tolerance) &&
                             walls.segmentClear(a, b);
      if (!segmentInside(inside ? plan.route_area : planned.free_area, a, b, 1e3 * tolerance) &&
          !excursion) {
        fail("leg " + std::to_string(i) + " leaves the " +
             (inside ? "route area and comes nearer than the wall distance" : "free area"));
        return result;
      }
    }
    result.oracle = vertexCount(planned.free_area) <= options.oracle_max_vertices;
    if (!result.oracle && vertexCount(map.mission.polygon) <= options.oracle_max_vertices) {
      std::cerr << "note: " << family << " seed " << map.seed << ": cleaning left "
                << vertexCount(planned.free_area) << " vertices, over the oracle's bound"
                << std::endl;
    }
    // The unsmoothed trajectory first: the default one keeps the wall distance, or comes
    // no nearer than that one (which passes gaps narrower than two wall distances).
    TrajectoryFigures unsmoothed;
    for (const bool smoothing : {false, true}) {
      PlannerParameters parameters = map.mission.parameters;
      parameters.smoothing = smoothing;
      const std::string label = family + " seed " + std::to_string(map.seed) +
                                (smoothing ? ", default" : ", smoothing=false");
      const double least =
          smoothing ? std::min(parameters.wall_distance, unsmoothed.clearance_m) : 0.0;
      TrajectoryFigures figures;
      for (const std::string& failure :
           checkTrajectory(planned.free_area, plan, parameters, result.oracle, 1e3 * tolerance,
                           least, label, &result, &figures)) {
        fail(std::string(smoothing ? "default: " : "smoothing=false: ") + failure);
      }
      if (!smoothing) {
        unsmoothed = figures;
      } else if (parameters.wall_distance > 0.0 && unsmoothed.traversal_time_s > 0.0) {
        result.default_trajectory =
            DefaultTrajectory{figures, parameters.wall_distance, unsmoothed.traversal_time_s};
      }
    }
  } catch (const UnreachableGoalError& error) {
    std::cerr << "refused " << family << " seed " << map.seed << ": " << error.what() << std::endl;
    result.refused = true;
  } catch (const InvalidInputError& error) {
    fail(std::string("exit 2 on a valid map: ") + error.what());
  } catch (const std::exception& error) {
    fail(std::string("exit 1: ") + error.what());
  }
  return result;
}

double quantile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<std::size_t>(std::ceil(q * values.size()));
  return values[std::min(values.size() - 1, rank == 0 ? 0 : rank - 1)];
}

/// The maps of one batch and what they showed.
struct BatchTally {
  int maps = 0;
  int failed = 0;
  int refused = 0;
  int split = 0;
  int with_oracle = 0;
  double coverage_difference = 0.0;
  double unseen_difference = 0.0;
  std::size_t max_vertices = 0;
  std::vector<double> times;
  /// Of the default trajectories: the least clearance / wall_distance, the maps under 1
  /// (beyond kClearanceTolerance), the turns, and the time ratios to the unsmoothed ones.
  double least_clearance_share = std::numeric_limits<double>::infinity();
  int nearer = 0;
  int turns_smoothed = 0;
  int turns_total = 0;
  std::vector<double> time_ratios;

  void add(const MapResult& result, std::size_t vertices) {
    ++maps;
    failed += result.failed ? 1 : 0;
    refused += result.refused ? 1 : 0;
    split += result.split ? 1 : 0;
    with_oracle += result.oracle_measured == 2 ? 1 : 0;
    coverage_difference = std::max(coverage_difference, result.coverage_difference_percent);
    unseen_difference = std::max(unseen_difference, result.unseen_difference_percent);
    max_vertices = std::max(max_vertices, vertices);
    if (!result.refused) times.push_back(result.planning_time_s);
    if (const std::optional<DefaultTrajectory>& trajectory = result.default_trajectory) {
      const TrajectoryFigures& figures = trajectory->figures;
      least_clearance_share =
          std::min(least_clearance_share, figures.clearance_m / trajectory->wall_distance);
      nearer += keepsClearance(figures.clearance_m, trajectory->wall_distance) ? 0 : 1;
      turns_smoothed += figures.turns_smoothed;
      turns_total += figures.turns_total;
      time_ratios.push_back(figures.traversal_time_s / trajectory->unsmoothed_time_s);
    }
  }
};

/// Runs one family's batches of maps, a table row each; returns the number of failed maps.
int runFamily(testing::MapFamily family, const Options& options) {
  const testing::HardMapGenerator generator(family);
  const std::string name = testing::HardMapGenerator::name(family);
  int failed = 0;
  int done = 0;
  std::uint64_t seed = options.first_seed;
  std::uint64_t passed_over = 0;
  for (const int batch_size : options.batches) {
    BatchTally tally;
    while (tally.maps < batch_size) {
      const testing::HardMap map = generator.generate(seed++);
      const std::size_t vertices = vertexCount(map.mission.polygon);
      if (vertices > options.max_vertices) {
        if (++passed_over > kMaxPassedOver) {
          std::cout << "FAIL " << name << ": no map of at most " << options.max_vertices
                    << " vertices in " << kMaxPassedOver << " seeds" << std::endl;
          return failed + 1;
        }
        continue;
      }
      passed_over = 0;
      tally.add(runMap(map, options), vertices);
      if (++done % 20 == 0) {
        std::cerr << "progress: " << name << " " << done << " maps (up to seed " << seed - 1
                  << "), " << failed + tally.failed << " failed" << std::endl;
      }
    }
    failed += tally.failed;
    struct rusage usage {};
    getrusage(RUSAGE_SELF, &usage);
    const std::vector<double>& times = tally.times;
    std::cout << std::fixed << "| " << name << ", maps " << done - tally.maps + 1 << "-" << done
              << " | " << tally.maps << " | " << tally.max_vertices << " | " << tally.split << " | "
              << tally.refused << " | " << tally.failed << " | " << std::setprecision(3)
              << tally.least_clearance_share << " | " << tally.nearer << " | "
              << std::setprecision(1)
              << (tally.turns_total > 0 ? 100.0 * tally.turns_smoothed / tally.turns_total : 0.0)
              << " | " << std::setprecision(3) << quantile(tally.time_ratios, 0.5) << " | "
              << tally.with_oracle << " | " << std::setprecision(3) << tally.coverage_difference
              << " | " << tally.unseen_difference << " | " << quantile(times, 0.5) << " | "
              << (times.empty() ? 0.0 : *std::max_element(times.begin(), times.end())) << " | "
              << std::setprecision(0) << usage.ru_maxrss / 1024.0 << " |" << std::endl;
  }
  return failed;
}

}  // namespace
}  // namespace kinematic_coverage::core

int main(int argc, char** argv) {
  using namespace kinematic_coverage::core;
  const Options options = parseOptions(argc, argv);
  std::cout << "| family, maps | maps | most vertices | planned in several parts | goal "
               "unreachable (refused) | failed | closest approach / wall_distance, least | "
               "maps nearer than wall_distance | turns smoothed % | traversal time ratio to "
               "unsmoothed, median | oracle checked | "
               "coverage_percent against the oracle, largest difference | unseen reachable "
               "against the oracle, largest difference (% of free area) | median plan s "
               "(timing) | max plan s (timing) | peak RSS MB (at most 2048) |\n"
               "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
            << std::endl;
  bool any_failed = false;
  for (const testing::MapFamily family : options.families) {
    std::cout.flush();
    const pid_t child = fork();
    if (child < 0) {
      std::perror("family_soak: fork");
      return 1;
    }
    if (child == 0) {
      const int failed = runFamily(family, options);
      std::cout.flush();
      std::_Exit(failed == 0 ? 0 : 1);
    }
    int status = 0;
    waitpid(child, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
      any_failed = true;
      if (!WIFEXITED(status)) {
        std::cout << "FAIL " << testing::HardMapGenerator::name(family) << ": crashed" << std::endl;
      }
    }
  }
  return any_failed ? 1 : 0;
}
