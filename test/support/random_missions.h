#pragma once

#include <cmath>
#include <cstdint>
#include <random>

#include "coverage_system/mission/mission.h"
#include "test/support/random_polygons.h"

namespace kinematic_coverage::core {
namespace testing {

/// m: the range of the hull's size and of the footprint's width.
constexpr double kMinHullSize = 50.0;
constexpr double kMaxHullSize = 200.0;
constexpr double kMinFootprintWidth = 2.0;
constexpr double kMaxFootprintWidth = 12.9;

/// A seeded random mission as the planner's tests size them: a hull 50 to 200 m across with up to
/// `holes_max` holes, a footprint 2 to 12.9 m wide, a wall distance of 0.5 to 1.5 m and a
/// lateral overlap of 0.2 to 0.6; start and goal near two hull vertices, pulled inwards out
/// of every hole. Shared by the soak test and the smoothing comparison benchmark.
struct RandomMission {
  Mission mission;
  double size_m = 0.0;
  double footprint_width_m = 0.0;
};

inline RandomMission randomMission(std::uint64_t seed, int holes_max) {
  std::mt19937 rng(static_cast<std::mt19937::result_type>(seed));
  std::uniform_real_distribution<double> size(kMinHullSize, kMaxHullSize);
  std::uniform_real_distribution<double> footprint_width(kMinFootprintWidth, kMaxFootprintWidth);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  RandomMission random;
  random.size_m = size(rng);
  Mission& mission = random.mission;
  mission.polygon = randomMap(rng, random.size_m, holes_max, 2.5);
  PlannerParameters& parameters = mission.parameters;
  random.footprint_width_m = footprint_width(rng);
  parameters.sensor_distance =
      random.footprint_width_m / (2.0 * std::tan(0.5 * parameters.lateral_fov));
  parameters.wall_distance = 0.5 + unit(rng);
  parameters.lateral_overlap = 0.2 + 0.4 * unit(rng);
  const PolygonWithHoles& map = mission.polygon;
  mission.start = freePointNear(map, map.hull[0]);
  mission.goal = freePointNear(map, map.hull[map.hull.size() / 2]);
  return random;
}

}  // namespace testing
}  // namespace kinematic_coverage::core
