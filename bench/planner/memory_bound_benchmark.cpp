// Memory bound: a lake of about 300 m across with a 2 000-vertex shoreline and
// 50 islands, default parameters (config/default.yaml), planned as `coverage_tool plan`
// does (validate, clean, plan) and then smoothed (TrajectoryGenerator). Prints one row
// per stage with its time, result and the peak RSS so far (getrusage ru_maxrss), the
// cells and lanes of the chosen decomposition, and exits with status 1 when the peak RSS
// reaches kMaxPeakRssMiB or validation, cleaning and planning take kMaxPlanningSeconds or
// longer. The map is seeded, so a run is deterministic.
//
//   memory_bound_benchmark [--seed 1] [--holes 50] [--vertices 2000] [--no-smoothing]

#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <random>
#include <string>
#include <vector>

#include "coverage_system/mission/mission_planner.h"
#include "coverage_system/mission/trajectory_pipeline.h"
#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/base/elapsed_seconds.h"
#include "polygon_coverage_ros_bridge/decomposition/best_decomposition.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"
#include "polygon_coverage_ros_bridge/sweeps/sweep_pattern.h"
#include "trajectory_generation_tools/trajectory/trajectory_generator.h"

namespace kinematic_coverage::core {
namespace {

/// The bounds this map must plan within (docs/RELIABILITY.md, Memory bound).
constexpr double kMaxPeakRssMiB = 1024.0;
constexpr double kMaxPlanningSeconds = 30.0;
/// Mean shoreline radius, metres, and the harmonics that shape bays and headlands: the
/// k-th has amplitude kHarmonicScale / k^1.5 metres (10.6 m for k = 2, 0.1 m for k = 40).
constexpr double kLakeRadius = 150.0;
constexpr int kHarmonics = 40;
constexpr double kHarmonicScale = 30.0;
/// Standard deviation of the per-vertex shoreline noise, metres.
constexpr double kShorelineNoise = 0.05;
/// Island radii (metres) and the least clearance between islands and to the shore.
constexpr double kMinIslandRadius = 3.0;
constexpr double kMaxIslandRadius = 10.0;
constexpr double kIslandGap = 5.0;

/// What the command line asks for.
struct BenchmarkOptions {
  unsigned seed = 1;
  int holes = 50;
  int vertices = 2000;
  bool smoothing = true;
};

BenchmarkOptions parseOptions(int argc, char** argv) {
  const auto usage = [] {
    std::fprintf(stderr,
                 "usage: memory_bound_benchmark [--seed 1] [--holes 50] [--vertices 2000] "
                 "[--no-smoothing]\n");
    std::exit(2);
  };
  BenchmarkOptions options;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--no-smoothing") {
      options.smoothing = false;
      continue;
    }
    if (i + 1 >= argc) usage();
    const int value = std::atoi(argv[++i]);
    if (flag == "--seed" && value >= 0) {
      options.seed = static_cast<unsigned>(value);
    } else if (flag == "--holes" && value >= 0) {
      options.holes = value;
    } else if (flag == "--vertices" && value >= 3) {
      options.vertices = value;
    } else {
      usage();
    }
  }
  return options;
}

/// Peak resident set size of this process so far, MiB (ru_maxrss is in KiB on Linux).
double peakRssMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

/// A lake shoreline (counter-clockwise, star-shaped about the origin): harmonics with
/// random phases and decaying amplitudes plus small per-vertex noise.
Ring shoreline(std::mt19937& rng, int vertices) {
  std::uniform_real_distribution<double> phase(0.0, 2.0 * M_PI);
  std::normal_distribution<double> noise(0.0, kShorelineNoise);
  std::vector<double> phases;
  for (int k = 0; k <= kHarmonics; ++k) phases.push_back(phase(rng));
  Ring hull;
  for (int i = 0; i < vertices; ++i) {
    const double a = 2.0 * M_PI * i / vertices;
    double r = kLakeRadius + noise(rng);
    for (int k = 2; k <= kHarmonics; ++k) {
      r += kHarmonicScale / std::pow(k, 1.5) * std::sin(k * a + phases[k]);
    }
    hull.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return hull;
}

/// An island (clockwise): a star of 8 to 16 vertices with radii in [0.6, 1] x `radius`.
Ring island(std::mt19937& rng, const Point2& centre, double radius) {
  std::uniform_int_distribution<int> vertex_count(8, 16);
  std::uniform_real_distribution<double> scale(0.6, 1.0);
  const int n = vertex_count(rng);
  Ring ring;
  for (int i = n - 1; i >= 0; --i) {
    const double a = 2.0 * M_PI * i / n;
    ring.push_back(centre + radius * scale(rng) * Point2(std::cos(a), std::sin(a)));
  }
  return ring;
}

/// The seeded lake: the shoreline and up to `holes` islands, each kIslandGap clear of
/// the shore and of the other islands (their discs), and start and goal near the shore.
Mission lakeMission(const BenchmarkOptions& options) {
  std::mt19937 rng(options.seed);
  Mission mission;
  mission.polygon.hull = shoreline(rng, options.vertices);
  std::uniform_real_distribution<double> coordinate(-kLakeRadius, kLakeRadius);
  std::uniform_real_distribution<double> island_radius(kMinIslandRadius, kMaxIslandRadius);
  std::vector<std::pair<Point2, double>> discs;
  for (int attempt = 0; attempt < 100000 && static_cast<int>(discs.size()) < options.holes;
       ++attempt) {
    const Point2 centre(coordinate(rng), coordinate(rng));
    const double radius = island_radius(rng);
    bool fits = insideRing(centre, mission.polygon.hull) &&
                distanceToRing(centre, mission.polygon.hull) > radius + kIslandGap;
    for (const auto& [other, other_radius] : discs) {
      fits = fits && (centre - other).norm() > radius + other_radius + kIslandGap;
    }
    if (!fits) continue;
    discs.emplace_back(centre, radius);
    mission.polygon.holes.push_back(island(rng, centre, radius));
  }
  const Ring& hull = mission.polygon.hull;
  mission.start = 0.97 * hull.front();
  mission.goal = 0.97 * hull[hull.size() / 2];
  return mission;
}

/// Lanes of the chosen decomposition, over every cell and every lane direction it keeps
/// (each direction's lanes make four sweep patterns), in every part of the offset free area.
std::size_t laneCount(const PlannedMission& planned, const PlannerParameters& parameters) {
  std::size_t lanes = 0;
  for (const PolygonWithHoles& area : planned.plan.offset_parts) {
    const Decomposition decomposition = computeBestDecomposition(
        area, parameters.decomposition_type == "trapezoidal" ? DecompositionType::kTrapezoidal
                                                             : DecompositionType::kBoustrophedon);
    const FrustumSensor sensor = sensorOf(parameters);
    const SweepPatternGenerator generator(
        sensor, SweepPatternGenerator::laneEndInset(sensor, parameters.wall_distance), area);
    for (const Cell& cell : decomposition.cells) {
      for (double direction : cell.sweep_directions) {
        lanes += generator.lanes(cell.polygon, direction).size();
      }
    }
  }
  return lanes;
}

int run(const BenchmarkOptions& options) {
  const Mission mission = lakeMission(options);
  std::size_t vertices = mission.polygon.hull.size();
  for (const Ring& hole : mission.polygon.holes) vertices += hole.size();
  std::printf("lake: seed %u, %zu-vertex shoreline, %zu islands, %zu vertices, %.0f m^2\n",
              options.seed, mission.polygon.hull.size(), mission.polygon.holes.size(), vertices,
              area(mission.polygon));
  std::printf("peak RSS before planning: %.1f MiB\n\n", peakRssMiB());
  std::printf(
      "| stage | seconds (timing) | peak RSS MiB (at most 1024) | result |\n|---|---|---|---|\n");
  const auto report = [](const PlanningStage& stage) {
    std::printf("| %s | %.3f | %.1f | %s |\n", stage.name.c_str(), stage.duration_s, peakRssMiB(),
                stage.summary.c_str());
    std::fflush(stdout);
  };
  const PlannedMission planned = planMission(mission, report);
  const double planning_rss = peakRssMiB();
  std::printf("| plan total | %.3f | %.1f | %zu cells, %zu waypoints |\n", planned.planning_time_s,
              planning_rss, planned.plan.cells.size(), planned.plan.waypoints.size());
  if (options.smoothing) {
    const auto started = std::chrono::steady_clock::now();
    const GeneratedTrajectory trajectory =
        TrajectoryPipeline(mission.parameters, planned.plan.exact_offset_parts)
            .trajectory(planned.plan.waypoints, planned.free_area);
    const double seconds = secondsSince(started);
    std::printf("| smoothing | %.3f | %.1f | %zu primitives, %zu poses, %.1f m, %.0f s |\n",
                seconds, peakRssMiB(), trajectory.path.size(), trajectory.poses.size(),
                trajectory.trajectory_length_m, trajectory.traversal_time_s);
  }
  const std::size_t lanes = laneCount(planned, mission.parameters);
  const double peak = peakRssMiB();
  std::printf("\ncells %zu, lanes %zu (over every cell and kept direction), waypoints %zu\n",
              planned.plan.cells.size(), lanes, planned.plan.waypoints.size());
  std::printf("planning %.3f s (bound %.0f s), peak RSS %.1f MiB (bound %.0f MiB)\n",
              planned.planning_time_s, kMaxPlanningSeconds, peak, kMaxPeakRssMiB);
  const bool within = planned.planning_time_s < kMaxPlanningSeconds && peak < kMaxPeakRssMiB;
  std::printf("%s\n", within ? "within bounds" : "BOUND BROKEN");
  return within ? 0 : 1;
}

}  // namespace
}  // namespace kinematic_coverage::core

int main(int argc, char** argv) {
  try {
    return kinematic_coverage::core::run(kinematic_coverage::core::parseOptions(argc, argv));
  } catch (const std::exception& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 1;
  }
}
