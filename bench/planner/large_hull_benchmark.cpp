// Planning time on a large hull: a shoreline of N vertices (radius 90 m with two
// harmonics and 5 cm noise) around one square hole, default parameters. Prints one row
// per planning stage and the total.
//
//   large_hull_benchmark [VERTICES]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "coverage_system/planner/coverage_planner.h"

int main(int argc, char** argv) {
  using kinematic_coverage::core::Point2;
  const int vertices = argc > 1 ? std::max(3, std::atoi(argv[1])) : 2000;
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 0.05);
  kinematic_coverage::core::PolygonWithHoles map;
  for (int i = 0; i < vertices; ++i) {
    const double a = 2.0 * M_PI * i / vertices;
    const double r = 90.0 + 8.0 * std::sin(3.0 * a) + 4.0 * std::sin(7.0 * a) + noise(rng);
    map.hull.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  map.holes.push_back({{-10, -10}, {-10, 10}, {10, 10}, {10, -10}});
  const auto plan =
      kinematic_coverage::core::CoveragePlanner(kinematic_coverage::core::PlannerParameters{})
          .plan(map, Point2(0, 50), Point2(0, -50));
  std::printf("| stage | seconds (timing) | result |\n|---|---|---|\n");
  for (const auto& stage : plan.stages) {
    std::printf("| %s | %.3f | %s |\n", stage.name.c_str(), stage.duration_s,
                stage.summary.c_str());
  }
  std::printf("| total | %.3f | %d-vertex hull |\n", plan.planning_time_s, vertices);
  return 0;
}
