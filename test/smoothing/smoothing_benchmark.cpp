// Times PathSmoother on a 10 000-waypoint boustrophedon path: lanes 100 m long and 2 m
// apart, r = 1, 20 rectangular obstacles beside the lanes. Prints the median of 21 runs.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "trajectory_generation_tools/smoothing/path_smoother.h"

int main() {
  using kinematic_coverage::PathSmoother;
  using kinematic_coverage::Point2;
  using kinematic_coverage::PolygonWithHoles;
  constexpr int kLanes = 5000;
  std::vector<Point2> waypoints;
  for (int i = 0; i < kLanes; ++i) {
    const double x = 2.0 * i;
    waypoints.push_back({x, i % 2 == 0 ? 0.0 : 100.0});
    waypoints.push_back({x, i % 2 == 0 ? 100.0 : 0.0});
  }
  const double width = 2.0 * (kLanes - 1);
  PolygonWithHoles area;
  area.hull = {{-10, -10}, {width + 10, -10}, {width + 10, 110}, {-10, 110}};
  for (int k = 0; k < 20; ++k) {
    const double x = width * k / 20.0 + 3.0;
    const double y = k % 2 == 0 ? 103.0 : -7.0;  // beyond the lane ends, clear of the turns
    area.holes.push_back({{x, y}, {x, y + 4}, {x + 6, y + 4}, {x + 6, y}});
  }
  std::vector<double> times;
  kinematic_coverage::SmoothedPath path;
  for (int run = 0; run < 21; ++run) {
    const auto start = std::chrono::steady_clock::now();
    const PathSmoother smoother(area, 1.0);
    path = smoother.smooth(waypoints);
    times.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count());
  }
  std::sort(times.begin(), times.end());
  std::printf("waypoints %zu primitives %zu turns %d smoothed %d inner %d bisector %d tangent %d\n",
              waypoints.size(), path.primitives.size(), path.statistics.turns_total,
              path.statistics.turns_smoothed, path.statistics.inner, path.statistics.outer_bisector,
              path.statistics.outer_tangent);
  std::printf("smoothing time: median %.3f ms, min %.3f ms, max %.3f ms\n", times[10], times[0],
              times[20]);
  return 0;
}
