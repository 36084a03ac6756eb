#include "test/support/lake_map_generator.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "test/support/random_polygons.h"

namespace kinematic_coverage::core {
namespace testing {
namespace {

/// Obstacle radii (m) and the least distance (m) of an obstacle from the shore and from
/// the other obstacle: room for the 1 m wall offset on both sides and a lane between.
constexpr double kMinRadius = 2.0;
constexpr double kMaxRadius = 5.0;
constexpr double kGap = 2.5;
/// Placement attempts per obstacle before the map is drawn again from the next numbers.
constexpr int kAttempts = 200;

/// A rectangle of half-diagonal `radius` about `centre`, turned by a random angle,
/// counter-clockwise.
Ring turnedRectangle(std::mt19937& rng, const Point2& centre, double radius) {
  std::uniform_real_distribution<double> angle(0.0, M_PI);
  std::uniform_real_distribution<double> aspect(0.25, 0.75);
  const double turn = angle(rng);
  const double half_diagonal_angle = 0.5 * M_PI * aspect(rng);
  Ring ring;
  for (const double corner : {half_diagonal_angle, M_PI - half_diagonal_angle,
                              M_PI + half_diagonal_angle, 2.0 * M_PI - half_diagonal_angle}) {
    ring.push_back(centre + radius * Point2(std::cos(turn + corner), std::sin(turn + corner)));
  }
  return ring;
}

}  // namespace

Mission LakeMapGenerator::generate(std::uint64_t seed) const {
  std::mt19937 rng(static_cast<std::mt19937::result_type>(seed));
  std::uniform_real_distribution<double> coordinate(kGap + kMinRadius, kSide - kGap - kMinRadius);
  std::uniform_real_distribution<double> radius(kMinRadius, kMaxRadius);
  std::uniform_int_distribution<int> vertices(3, 8);
  Mission mission;
  PolygonWithHoles& map = mission.polygon;
  map.hull = {{0.0, 0.0}, {kSide, 0.0}, {kSide, kSide}, {0.0, kSide}};
  mission.start = Point2(1.0, 1.0);
  mission.goal = Point2(kSide - 1.0, kSide - 1.0);
  while (map.holes.size() < 2) {
    for (int attempt = 0; attempt < kAttempts && map.holes.size() < 2; ++attempt) {
      const Point2 centre(coordinate(rng), coordinate(rng));
      const double r = radius(rng);
      // 8 "vertices" draws a turned rectangle; 3 to 7 a star-shaped polygon.
      const int n = vertices(rng);
      Ring hole =
          n == 8 ? turnedRectangle(rng, centre, r) : randomStarRing(rng, centre, 0.5 * r, r, n);
      bool fits = ringDistance(hole, map.hull) > kGap && distanceToRing(centre, map.hull) > r;
      for (const Ring& other : map.holes) fits = fits && ringDistance(hole, other) > kGap;
      for (const Point2& end : {mission.start, mission.goal}) {
        fits = fits && !insideRing(end, hole) && distanceToRing(end, hole) > kGap;
      }
      if (!fits) continue;
      std::reverse(hole.begin(), hole.end());  // holes clockwise
      map.holes.push_back(std::move(hole));
    }
    if (map.holes.size() < 2) map.holes.clear();
  }
  // The Chapter 4 experiment's settings (config/missions/lake_30x30.yaml).
  PlannerParameters& p = mission.parameters;
  p.decomposition_type = "boustrophedon";
  p.cost_function = "time";
  p.wall_distance = 1.0;
  p.sensor_model = "frustum";
  p.lateral_fov = 2.27;
  p.onward_fov = 0.52;
  p.sensor_distance = 3.0;
  p.lateral_overlap = 0.4;
  p.turning_radius = 1.0;
  p.segment_sampling_distance = 0.5;
  p.arc_sampling_distance = 0.1;
  return mission;
}

}  // namespace testing
}  // namespace kinematic_coverage::core
