#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {
namespace testing {

/// A star-shaped random ring around `centre` (counter-clockwise), radii in [r_min, r_max].
inline Ring randomStarRing(std::mt19937& rng, const Point2& centre, double r_min, double r_max,
                           int vertices) {
  std::uniform_real_distribution<double> radius(r_min, r_max);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  Ring ring;
  for (int i = 0; i < vertices; ++i) {
    const double angle = (i + 0.5 + jitter(rng)) * 2.0 * M_PI / vertices;
    const double r = radius(rng);
    ring.push_back(centre + r * Point2(std::cos(angle), std::sin(angle)));
  }
  return ring;
}

/// Distance between the boundaries of two rings (0 when their edges cross).
inline double ringDistance(const Ring& a, const Ring& b) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Point2& p = a[i];
    const Point2& q = a[(i + 1) % a.size()];
    for (std::size_t j = 0; j < b.size(); ++j) {
      const Point2& r = b[j];
      const Point2& t = b[(j + 1) % b.size()];
      const bool crossing =
          cross(p, q, r) * cross(p, q, t) < 0.0 && cross(r, t, p) * cross(r, t, q) < 0.0;
      if (crossing) return 0.0;
      best = std::min({best, distanceToSegment(p, r, t), distanceToSegment(q, r, t),
                       distanceToSegment(r, p, q), distanceToSegment(t, p, q)});
    }
  }
  return best;
}

/// A random map: a star-shaped hull about `size` across with up to `max_holes` disjoint
/// star-shaped holes, each at least `gap` from the hull and from every other hole.
inline PolygonWithHoles randomMap(std::mt19937& rng, double size, int max_holes, double gap) {
  PolygonWithHoles map;
  std::uniform_int_distribution<int> hull_vertices(4, 12);
  map.hull = randomStarRing(rng, {0, 0}, 0.38 * size, 0.5 * size, hull_vertices(rng));
  std::uniform_int_distribution<int> hole_count(0, max_holes);
  std::uniform_int_distribution<int> hole_vertices(3, 7);
  std::uniform_real_distribution<double> coordinate(-0.4 * size, 0.4 * size);
  std::uniform_real_distribution<double> hole_radius(0.03 * size, 0.09 * size);
  const int wanted = hole_count(rng);
  for (int attempt = 0; attempt < 200 && static_cast<int>(map.holes.size()) < wanted; ++attempt) {
    const Point2 centre(coordinate(rng), coordinate(rng));
    const double r = hole_radius(rng);
    Ring hole = randomStarRing(rng, centre, 0.5 * r, r, hole_vertices(rng));
    bool fits = insideRing(centre, map.hull) && distanceToRing(centre, map.hull) > r + gap;
    fits = fits && ringDistance(hole, map.hull) > gap;
    for (const Ring& other : map.holes) {
      fits = fits && ringDistance(hole, other) > gap;
      fits = fits && !insideRing(hole.front(), other) && !insideRing(other.front(), hole);
    }
    if (!fits) continue;
    std::reverse(hole.begin(), hole.end());  // holes clockwise
    map.holes.push_back(std::move(hole));
  }
  return map;
}

/// A start or goal near a hull vertex (in the wall band or beyond it): the vertex scaled
/// by 0.95 about the origin, pulled towards the origin until it is out of every hole.
inline Point2 freePointNear(const PolygonWithHoles& map, const Point2& vertex) {
  Point2 p = 0.95 * vertex;
  for (int k = 0; k < 20; ++k) {
    bool in_hole = false;
    for (const Ring& hole : map.holes) in_hole = in_hole || insideRing(p, hole);
    if (!in_hole) break;
    p *= 0.9;
  }
  return p;
}

}  // namespace testing
}  // namespace kinematic_coverage::core
