#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "test/support/random_polygons.h"

namespace kinematic_coverage::core {
namespace testing {

/// A square map [0, size]^2 with up to `max_holes` disjoint convex holes (clockwise),
/// each with `min_vertices` to `max_vertices` vertices on a circle, at least `gap` apart.
inline PolygonWithHoles convexHolesMap(std::mt19937& rng, double size, int max_holes,
                                       int min_vertices, int max_vertices, double gap) {
  PolygonWithHoles map;
  map.hull = {{0, 0}, {size, 0}, {size, size}, {0, size}};
  std::uniform_real_distribution<double> radius(0.03 * size, 0.08 * size);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> vertex_count(min_vertices, max_vertices);
  std::vector<std::pair<Point2, double>> discs;
  for (int attempt = 0; attempt < 2000 && static_cast<int>(discs.size()) < max_holes; ++attempt) {
    const double r = radius(rng);
    const Point2 centre(r + gap + unit(rng) * (size - 2 * (r + gap)),
                        r + gap + unit(rng) * (size - 2 * (r + gap)));
    const bool apart = std::all_of(discs.begin(), discs.end(), [&](const auto& disc) {
      return (disc.first - centre).norm() > disc.second + r + gap;
    });
    if (!apart) continue;
    discs.emplace_back(centre, r);
    const int n = vertex_count(rng);
    std::vector<double> angles;
    const double offset = unit(rng) * 2.0 * M_PI;
    for (int i = 0; i < n; ++i) angles.push_back(offset + (i + 0.35 * unit(rng)) * 2.0 * M_PI / n);
    Ring hole;
    for (auto it = angles.rbegin(); it != angles.rend(); ++it) {
      hole.push_back(centre + r * Point2(std::cos(*it), std::sin(*it)));  // clockwise
    }
    map.holes.push_back(hole);
  }
  return map;
}

/// Shortest path lengths between given points by brute force: Dijkstra over every ring
/// vertex, visibility checked with planar_geometry's segmentInside.
class BruteForceRouter {
 public:
  BruteForceRouter(const PolygonWithHoles& map, const std::vector<Point2>& points, double tolerance)
      : points_(points) {
    std::vector<Point2> vertices = map.hull;
    for (const Ring& hole : map.holes) vertices.insert(vertices.end(), hole.begin(), hole.end());
    const std::size_t n = vertices.size();
    std::vector<double> weight(n * n, kNone);
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 1; j < n; ++j) {
        if (segmentInside(map, vertices[i], vertices[j], tolerance)) {
          weight[i * n + j] = weight[j * n + i] = (vertices[i] - vertices[j]).norm();
        }
      }
    }
    // Each point's straight distance to the vertices it sees, then Dijkstra from it.
    std::vector<std::vector<double>> sees(points.size(), std::vector<double>(n, kNone));
    for (std::size_t p = 0; p < points.size(); ++p) {
      for (std::size_t i = 0; i < n; ++i) {
        if (segmentInside(map, points[p], vertices[i], tolerance)) {
          sees[p][i] = (points[p] - vertices[i]).norm();
        }
      }
    }
    distances_.assign(points.size() * points.size(), kNone);
    for (std::size_t p = 0; p < points.size(); ++p) {
      std::vector<double> best = sees[p];
      std::vector<bool> done(n, false);
      for (std::size_t round = 0; round < n; ++round) {
        std::size_t u = n;
        for (std::size_t i = 0; i < n; ++i) {
          if (!done[i] && best[i] < kNone && (u == n || best[i] < best[u])) u = i;
        }
        if (u == n) break;
        done[u] = true;
        for (std::size_t w = 0; w < n; ++w)
          best[w] = std::min(best[w], best[u] + weight[u * n + w]);
      }
      for (std::size_t q = 0; q < points.size(); ++q) {
        double d = segmentInside(map, points[p], points[q], tolerance)
                       ? (points[p] - points[q]).norm()
                       : kNone;
        for (std::size_t w = 0; w < n; ++w) d = std::min(d, best[w] + sees[q][w]);
        distances_[p * points.size() + q] = d;
      }
    }
  }

  /// The shortest path length from points[i] to points[j].
  double distance(std::size_t i, std::size_t j) const { return distances_[i * points_.size() + j]; }

 private:
  static constexpr double kNone = std::numeric_limits<double>::infinity();
  std::vector<Point2> points_;
  std::vector<double> distances_;
};

/// Query points of a map: random interior points, points on random boundary edges and
/// ring vertices, like sweep ends on the offset boundary.
inline std::vector<Point2> queryPoints(std::mt19937& rng, const PolygonWithHoles& map, int interior,
                                       int on_boundary, int vertices) {
  std::vector<Point2> points;
  Eigen::Vector2d low = map.hull.front();
  Eigen::Vector2d high = map.hull.front();
  for (const Point2& p : map.hull) low = low.cwiseMin(p), high = high.cwiseMax(p);
  std::uniform_real_distribution<double> x(low.x(), high.x());
  std::uniform_real_distribution<double> y(low.y(), high.y());
  while (static_cast<int>(points.size()) < interior) {
    const Point2 p(x(rng), y(rng));
    if (contains(map, p)) points.push_back(p);
  }
  std::vector<const Ring*> rings = {&map.hull};
  for (const Ring& hole : map.holes) rings.push_back(&hole);
  std::uniform_int_distribution<std::size_t> ring_index(0, rings.size() - 1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < on_boundary + vertices; ++i) {
    const Ring& ring = *rings[ring_index(rng)];
    const std::size_t k = std::uniform_int_distribution<std::size_t>(0, ring.size() - 1)(rng);
    const Point2& a = ring[k];
    const Point2& b = ring[(k + 1) % ring.size()];
    points.push_back(i < on_boundary ? Point2(a + unit(rng) * (b - a)) : a);
  }
  return points;
}

/// A room [0, 50]^2 with a 2 m wide corridor leaving its right wall at y = 20..22; at
/// x = 80 the corridor turns left by `bend` radians, so its lower wall has a convex corner
/// at (80, 20), and the corridor's mouth has the reflex corners (50, 20) and (50, 22).
inline PolygonWithHoles bentCorridorMap(double bend) {
  const Point2 heading(std::cos(bend), std::sin(bend));
  const Point2 lower_bend(80, 20);
  const Point2 upper_bend(80, 22);
  return {{{0, 0},
           {50, 0},
           {50, 20},
           lower_bend,
           lower_bend + 10.0 * heading,
           upper_bend + 10.0 * heading,
           upper_bend,
           {50, 22},
           {50, 50},
           {0, 50}},
          {}};
}

/// The square [0, 10]^2 with a thin spike of wall rising from its bottom edge to the
/// reflex tip (5, 6); the spike is 2 * half_base wide at the bottom.
inline PolygonWithHoles wallSpikeMap(double half_base) {
  return {{{0, 0}, {5 - half_base, 0}, {5, 6}, {5 + half_base, 0}, {10, 0}, {10, 10}, {0, 10}}, {}};
}

/// The square [0, 10]^2 with a thin needle of free area leaving its right wall, 2 *
/// half_base wide there, with its convex tip at (16, 5).
inline PolygonWithHoles freeNeedleMap(double half_base) {
  return {{{0, 0}, {10, 0}, {10, 5 - half_base}, {16, 5}, {10, 5 + half_base}, {10, 10}, {0, 10}},
          {}};
}

/// A jagged star hull about 200 m across (`vertices` vertices, radii from r_min to 100)
/// around a square hole: deep thin bays and spikes, many nearly straight corners.
inline PolygonWithHoles jaggedStarMap(std::mt19937& rng, int vertices, double r_min) {
  PolygonWithHoles map;
  map.hull = randomStarRing(rng, {0, 0}, r_min, 100.0, vertices);
  map.holes.push_back({{-10, -10}, {-10, 10}, {10, 10}, {10, -10}});
  return map;
}

/// Points on the boundary of `map` as sweep lane ends are: on random edges, at vertices,
/// and on edges close to a vertex (log-uniform from a tenth of `tolerance` to a thousand
/// times it: just past a corner, or inside a sharp corner's sliver); each coordinate then
/// moved by -1e-14, 0 or +1e-14, a rounding error off the boundary.
inline std::vector<Point2> boundaryPoints(std::mt19937& rng, const PolygonWithHoles& map,
                                          double tolerance, int count) {
  std::vector<const Ring*> rings = {&map.hull};
  for (const Ring& hole : map.holes) rings.push_back(&hole);
  std::uniform_int_distribution<std::size_t> ring_index(0, rings.size() - 1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> nudge(-1, 1);
  std::vector<Point2> points;
  for (int i = 0; i < count; ++i) {
    const Ring& ring = *rings[ring_index(rng)];
    const std::size_t k = std::uniform_int_distribution<std::size_t>(0, ring.size() - 1)(rng);
    const Point2& a = ring[k];
    const Point2& b = ring[(k + 1) % ring.size()];
    const double length = (b - a).norm();
    Point2 p = a;
    if (i % 4 == 0) {
      p = a + unit(rng) * (b - a);
    } else if (i % 4 != 1) {
      const double from_vertex =
          std::min(tolerance * std::pow(10.0, 4.0 * unit(rng) - 1.0), 0.5 * length);
      p = i % 4 == 2 ? Point2(a + (from_vertex / length) * (b - a))
                     : Point2(b + (from_vertex / length) * (a - b));
    }
    points.push_back(p + 1e-14 * Point2(nudge(rng), nudge(rng)));
  }
  return points;
}

}  // namespace testing
}  // namespace kinematic_coverage::core
