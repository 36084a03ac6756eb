#include "test/support/hard_map_generator.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <utility>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/validation/polygon_cleaner.h"
#include "polygon_coverage_ros_bridge/validation/polygon_validator.h"
#include "test/support/random_missions.h"
#include "test/support/random_polygons.h"

namespace kinematic_coverage::core {
namespace testing {
namespace {

/// Grid (m) of the touching_holes family: its coordinates are multiples of a power of two
/// over it, so that points on hull edges and shared hole edges are exact.
constexpr double kGrid = 0.25;
/// The rooms family's gap_clearance for a corridor narrower than 2 w, as a share of the
/// corridor's half-width (its clearance): the transit through its middle passes.
constexpr double kAllowedCorridorShare = 0.85;

double uniform(std::mt19937& rng, double low, double high) {
  return std::uniform_real_distribution<double>(low, high)(rng);
}

double logUniform(std::mt19937& rng, double low, double high) {
  return std::exp(uniform(rng, std::log(low), std::log(high)));
}

int integer(std::mt19937& rng, int low, int high) {
  return std::uniform_int_distribution<int>(low, high)(rng);
}

bool coin(std::mt19937& rng) { return std::bernoulli_distribution(0.5)(rng); }

double snap(double value) { return std::round(value / kGrid) * kGrid; }

/// Rotates every point of the mission by `angle` about the origin.
void rotate(Mission& mission, double angle) {
  const Eigen::Rotation2Dd rotation(angle);
  for (Point2& p : mission.polygon.hull) p = rotation * p;
  for (Ring& hole : mission.polygon.holes) {
    for (Point2& p : hole) p = rotation * p;
  }
  mission.start = rotation * mission.start;
  mission.goal = rotation * mission.goal;
}

/// Half the maps are turned by a random angle, so that no family is only axis-aligned.
void maybeRotate(std::mt19937& rng, Mission& mission) {
  if (coin(rng)) rotate(mission, uniform(rng, -M_PI, M_PI));
}

bool passesValidator(const PolygonWithHoles& polygon) {
  try {
    PolygonValidator().validate(polygon);
    return true;
  } catch (const InvalidInputError&) {
    return false;
  }
}

/// The cleaned free area, or nothing when validation or cleaning rejects the polygon.
std::optional<PolygonWithHoles> cleaned(const PolygonWithHoles& polygon) {
  try {
    PolygonValidator().validate(polygon);
    return PolygonCleaner().clean(polygon).free_area;
  } catch (const InvalidInputError&) {
    return std::nullopt;
  }
}

/// A random point of the bounding box of `ring` that `accept` takes (tries 1000 times, then
/// the ring's first vertex).
template <typename Accept>
Point2 pointWhere(std::mt19937& rng, const Ring& ring, Accept accept) {
  Point2 low = ring.front();
  Point2 high = ring.front();
  for (const Point2& p : ring) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  for (int attempt = 0; attempt < 1000; ++attempt) {
    const Point2 p(uniform(rng, low.x(), high.x()), uniform(rng, low.y(), high.y()));
    if (accept(p)) return p;
  }
  return ring.front();
}

/// A free point of `polygon` (inside the hull, outside every hole); in the wall band or
/// deeper inside alike.
Point2 freePoint(std::mt19937& rng, const PolygonWithHoles& polygon) {
  return pointWhere(rng, polygon.hull, [&](const Point2& p) {
    if (!insideRing(p, polygon.hull) || distanceToRing(p, polygon.hull) < 1e-3) return false;
    for (const Ring& hole : polygon.holes) {
      if (insideRing(p, hole) || distanceToRing(p, hole) < 1e-3) return false;
    }
    return true;
  });
}

/// The parameters every family varies, drawn first: footprint W in [1, 13] m and L in
/// [1, W] m from a sensor 1 to 4 m above the bottom, turning radius and wall distance in
/// [0.3, 2] m, lateral overlap in [0.1, 0.5], either decomposition.
void drawParameters(std::mt19937& rng, HardMap& map) {
  PlannerParameters& p = map.mission.parameters;
  map.footprint_width_m = logUniform(rng, 1.0, 13.0);
  map.footprint_length_m = uniform(rng, 1.0, map.footprint_width_m);
  p.sensor_distance = uniform(rng, 1.0, 4.0);
  p.lateral_fov = 2.0 * std::atan(map.footprint_width_m / (2.0 * p.sensor_distance));
  p.onward_fov = 2.0 * std::atan(map.footprint_length_m / (2.0 * p.sensor_distance));
  p.turning_radius = uniform(rng, 0.3, 2.0);
  p.wall_distance = uniform(rng, 0.3, 2.0);
  p.lateral_overlap = uniform(rng, 0.1, 0.5);
  p.decomposition_type = coin(rng) ? "boustrophedon" : "trapezoidal";
}

/// A comb: a base strip with 3 to 8 rectilinear teeth (dead-end bays) on top; at least one
/// tooth narrower than 2 w (0.55 to 0.95 of it) and one wider (a little, or by footprints).
void comb(std::mt19937& rng, bool small, HardMap& map) {
  const double w = map.mission.parameters.wall_distance;
  const double W = map.footprint_width_m;
  const int teeth = small ? 2 : integer(rng, 3, 8);
  std::vector<bool> narrow(teeth);
  for (int i = 0; i < teeth; ++i) narrow[i] = i == 0 || (i > 1 && coin(rng));
  std::shuffle(narrow.begin(), narrow.end(), rng);
  const double base = uniform(rng, 2.5 * w, 4.0 * w + W);
  double x = uniform(rng, w, 3.0 * w + 0.5 * W);  // left margin
  Ring top;                                       // tooth outlines, left to right
  for (int i = 0; i < teeth; ++i) {
    double width = 0.0;
    if (narrow[i]) {
      width = 2.0 * w * uniform(rng, 0.55, 0.95);
    } else {
      width = coin(rng) ? 2.0 * w * uniform(rng, 1.05, 1.5) : 2.0 * w + uniform(rng, 0.2, 2.0) * W;
    }
    const double depth = uniform(rng, 3.0 * w, 8.0 * w + 2.0 * W);
    top.emplace_back(x, base);
    top.emplace_back(x, base + depth);
    top.emplace_back(x + width, base + depth);
    top.emplace_back(x + width, base);
    map.passage_widths_m.push_back(width);
    x += width + uniform(rng, 0.2, 2.0);  // the solid wall between two teeth
  }
  const double length = x + uniform(rng, w, 3.0 * w + 0.5 * W);
  Ring& hull = map.mission.polygon.hull;
  hull = {{0.0, 0.0}, {length, 0.0}, {length, base}};
  hull.insert(hull.end(), top.rbegin(), top.rend());
  hull.emplace_back(0.0, base);
  map.mission.start = {uniform(rng, 0.05, 0.95) * length, uniform(rng, 0.05, 0.95) * base};
  const std::size_t tooth = 4 * static_cast<std::size_t>(integer(rng, 0, teeth - 1));
  const Point2 bay_low = top[tooth];
  const Point2 bay_high = top[tooth + 2];
  map.mission.goal = {0.5 * (bay_low.x() + bay_high.x()),
                      base + uniform(rng, 0.2, 0.9) * (bay_high.y() - base)};
  maybeRotate(rng, map.mission);
}

/// A square spiral corridor turning left, 4 to 12 legs, `c` wide, its arms `s` apart;
/// start at the outer end, goal at the inner end.
void spiral(std::mt19937& rng, bool small, HardMap& map) {
  const double w = map.mission.parameters.wall_distance;
  const double c = logUniform(rng, 2.5 * w, std::max(3.0 * w, 3.0 * map.footprint_width_m));
  const double pitch = c + uniform(rng, 0.2, 2.0);
  const int legs = integer(rng, 4, small ? 5 : 12);
  const double first =
      (std::floor((legs - 2) / 2.0) + 1.0) * pitch + c + uniform(rng, 0.0, 1.0) * c;
  std::vector<Point2> centre{{0.0, 0.0}};
  const Point2 directions[] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  for (int j = 0; j < legs; ++j) {
    const double leg = j == 0 ? first : first - std::floor((j - 1) / 2.0) * pitch;
    centre.push_back(centre.back() + leg * directions[j % 4]);
  }
  // Mitred offsets of the centre line by c / 2 to either side.
  const double h = 0.5 * c;
  const auto normal = [&](int leg) {
    const Point2 d = directions[leg % 4];
    return Point2(-d.y(), d.x());
  };
  Ring left;
  Ring right;
  for (int j = 0; j <= legs; ++j) {
    Point2 offset = j == 0 ? normal(0) : j == legs ? normal(legs - 1) : normal(j - 1) + normal(j);
    left.push_back(centre[j] + h * offset);
    right.push_back(centre[j] - h * offset);
  }
  Ring& hull = map.mission.polygon.hull;
  hull = right;
  hull.insert(hull.end(), left.rbegin(), left.rend());
  if (signedArea(hull) < 0.0) std::reverse(hull.begin(), hull.end());
  const Point2 entry = centre[1] - centre[0];
  map.mission.start = centre[0] + uniform(rng, 0.05, 0.3) * entry;
  const Point2 last = centre[legs] - centre[legs - 1];
  map.mission.goal = centre[legs] - uniform(rng, 0.05, 0.3) * last;
  maybeRotate(rng, map.mission);
}

/// Two rectangular rooms joined by a straight corridor 0.8 to 0.97 or 1.03 to 1.25 times
/// 2 w wide; start in one room, goal in the other. A corridor narrower than 2 w is allowed
/// (gap_clearance 0.85 times its half-width), as an operator must for the goal to be reached.
void rooms(std::mt19937& rng, HardMap& map) {
  const double w = map.mission.parameters.wall_distance;
  const double W = map.footprint_width_m;
  const double low = std::max(4.0 * w, 1.5 * W);
  const double high = std::max(8.0 * w, 5.0 * W);
  const double a1 = uniform(rng, low, high);
  const double b1 = uniform(rng, low, high);
  const double a2 = uniform(rng, low, high);
  const double b2 = uniform(rng, low, high);
  const double corridor =
      2.0 * w * (coin(rng) ? uniform(rng, 0.8, 0.97) : uniform(rng, 1.03, 1.25));
  map.passage_widths_m.push_back(corridor);
  const double length = uniform(rng, w, 6.0 * w) + uniform(rng, 0.0, W);
  const double h = 0.5 * corridor;
  // Room B's bottom so that the rooms share a y range with room for the corridor.
  const double margin = 0.1;
  const double yb = uniform(rng, corridor + 2.0 * margin - b2, b1 - corridor - 2.0 * margin);
  const double shared_low = std::max(0.0, yb) + margin + h;
  const double shared_high = std::min(b1, yb + b2) - margin - h;
  const double yc = uniform(rng, shared_low, std::max(shared_low, shared_high));
  const double x2 = a1 + length;
  map.mission.polygon.hull = {{0, 0},       {a1, 0},       {a1, yc - h},       {x2, yc - h},
                              {x2, yb},     {x2 + a2, yb}, {x2 + a2, yb + b2}, {x2, yb + b2},
                              {x2, yc + h}, {a1, yc + h},  {a1, b1},           {0, b1}};
  map.mission.start = {uniform(rng, 0.05, 0.95) * a1, uniform(rng, 0.05, 0.95) * b1};
  map.mission.goal = {x2 + uniform(rng, 0.05, 0.95) * a2, yb + uniform(rng, 0.05, 0.95) * b2};
  if (h < w) map.mission.parameters.gap_clearance = kAllowedCorridorShare * h;
  maybeRotate(rng, map.mission);
}

/// A noisy star-shaped ring about `centre`: radius `r` times one plus cosines at three
/// scales and a per-vertex jitter (at most 0.45 in all, so the ring stays star-shaped).
Ring noisyRing(std::mt19937& rng, const Point2& centre, double r, int vertices) {
  struct Wave {
    double amplitude, frequency, phase;
  };
  std::vector<Wave> waves;
  waves.push_back({uniform(rng, 0.05, 0.2), static_cast<double>(integer(rng, 2, 4)), 0.0});
  waves.push_back({uniform(rng, 0.02, 0.1), static_cast<double>(integer(rng, 5, 12)), 0.0});
  waves.push_back({uniform(rng, 0.0, 0.05), static_cast<double>(integer(rng, 13, 40)), 0.0});
  for (Wave& wave : waves) wave.phase = uniform(rng, 0.0, 2.0 * M_PI);
  const double jitter = uniform(rng, 0.0, 0.05);
  Ring ring;
  for (int i = 0; i < vertices; ++i) {
    const double angle = 2.0 * M_PI * (i + uniform(rng, -0.3, 0.3)) / vertices;
    double radius = 1.0 + uniform(rng, -jitter, jitter);
    for (const Wave& wave : waves) {
      radius += wave.amplitude * std::cos(wave.frequency * angle + wave.phase);
    }
    ring.push_back(centre + r * radius * Point2(std::cos(angle), std::sin(angle)));
  }
  return ring;
}

/// `ring` warped by shears along x and along y (each one-to-one on the plane); bays and
/// headlands that a star-shaped ring cannot have.
Ring warped(const Ring& ring, double amplitude, double wavelength, double phase_x, double phase_y) {
  Ring result;
  for (const Point2& p : ring) {
    const double x = p.x() + amplitude * std::sin(p.y() / wavelength + phase_x);
    result.emplace_back(x, p.y() + amplitude * std::sin(x / wavelength + phase_y));
  }
  return result;
}

/// `star` (a shore `size` across) warped by warped() with an amplitude and a wavelength drawn
/// from the given ranges (fractions of `size`) and random phases, the amplitude halved until
/// the shore passes the validator (none left: `star` itself); counter-clockwise.
Ring warpedShore(std::mt19937& rng, const Ring& star, double size,
                 std::pair<double, double> amplitude_range,
                 std::pair<double, double> wavelength_range) {
  double amplitude = uniform(rng, amplitude_range.first, amplitude_range.second) * size;
  const double wavelength = uniform(rng, wavelength_range.first, wavelength_range.second) * size;
  const double phase_x = uniform(rng, 0.0, 2.0 * M_PI);
  const double phase_y = uniform(rng, 0.0, 2.0 * M_PI);
  Ring shore = warped(star, amplitude, wavelength, phase_x, phase_y);
  while (!passesValidator({shore, {}})) {
    amplitude *= 0.5;
    shore = amplitude < 1e-3 * size ? star : warped(star, amplitude, wavelength, phase_x, phase_y);
  }
  if (signedArea(shore) < 0.0) std::reverse(shore.begin(), shore.end());
  return shore;
}

/// Smallest distance from `island` to the shore and to every island in `others`, or -1 when
/// the island is not inside the shore or nests with another island.
double gapOf(const Ring& island, const Ring& shore, const std::vector<Ring>& others) {
  for (const Point2& p : island) {
    if (!insideRing(p, shore)) return -1.0;
  }
  double gap = ringDistance(island, shore);
  for (const Ring& other : others) {
    if (insideRing(island.front(), other) || insideRing(other.front(), island)) return -1.0;
    gap = std::min(gap, ringDistance(island, other));
  }
  return gap;
}

/// `shape` scaled by `s` about `centre`.
Ring scaled(const Ring& shape, const Point2& centre, double s) {
  Ring ring;
  for (const Point2& p : shape) ring.push_back(centre + s * (p - centre));
  return ring;
}

/// A noisy shore of 150 to 420 vertices, warped, with 2 to 8 noisy islands (150 to 600
/// vertices in all); the first one to half of the islands are grown until they come within
/// 0.15 to 0.95 times 2 w of the shore or of another island.
void shoreline(std::mt19937& rng, bool small, HardMap& map) {
  const double w = map.mission.parameters.wall_distance;
  const double size = std::clamp(map.footprint_width_m * uniform(rng, 8.0, 20.0), 30.0 * w, 200.0);
  const int shore_vertices = small ? 12 : integer(rng, 150, 420);
  const Ring star = noisyRing(rng, {0, 0}, 0.5 * size, shore_vertices);
  const Ring shore = warpedShore(rng, star, size, {0.0, 0.12}, {0.15, 0.4});
  const int islands = small ? integer(rng, 1, 2) : integer(rng, 2, 8);
  const int close = integer(rng, 1, std::max(1, islands / 2));
  int budget = static_cast<int>(HardMapGenerator::kMaxVertices) - shore_vertices;
  std::vector<Ring> placed;
  for (int i = 0; i < islands; ++i) {
    const int vertices = small ? 6 : std::min(integer(rng, 8, 30), budget / (islands - i));
    if (vertices < 6) break;
    const double target = 2.0 * w * uniform(rng, 0.15, 0.95);
    for (int attempt = 0; attempt < 50; ++attempt) {
      const Point2 centre = pointWhere(rng, shore, [&](const Point2& p) {
        return insideRing(p, shore) && distanceToRing(p, shore) > 0.02 * size;
      });
      const Ring shape = noisyRing(rng, centre, uniform(rng, 0.03, 0.08) * size, vertices);
      double fits = 0.05;
      double gap = gapOf(scaled(shape, centre, fits), shore, placed);
      if (gap <= (i < close ? target : 0.2)) continue;
      double s = 1.0;
      if (i < close) {
        // Grow until the gap falls to the target, then bisect back to just above it.
        double misses = fits;
        bool reached = false;
        while (!reached && misses < 3.0) {
          misses *= 1.5;
          reached = gapOf(scaled(shape, centre, misses), shore, placed) <= target;
          if (!reached) fits = misses;
        }
        if (!reached) continue;
        for (int k = 0; k < 40; ++k) {
          const double middle = 0.5 * (fits + misses);
          (gapOf(scaled(shape, centre, middle), shore, placed) > target ? fits : misses) = middle;
        }
        s = fits;
      }
      Ring island = scaled(shape, centre, s);
      gap = gapOf(island, shore, placed);
      if (i < close ? !(gap > 0.0 && gap < 2.0 * w) : gap <= 0.2) continue;
      placed.push_back(std::move(island));
      budget -= vertices;
      break;
    }
  }
  PolygonWithHoles& polygon = map.mission.polygon;
  polygon.hull = shore;
  for (Ring island : placed) {
    std::reverse(island.begin(), island.end());
    polygon.holes.push_back(std::move(island));
  }
  for (std::size_t i = 0; i < placed.size(); ++i) {
    std::vector<Ring> others = placed;
    others.erase(others.begin() + static_cast<std::ptrdiff_t>(i));
    map.island_gaps_m.push_back(gapOf(placed[i], shore, others));
  }
  map.mission.start = freePoint(rng, polygon);
  map.mission.goal = freePoint(rng, polygon);
}

/// A grid-aligned rectangle.
Ring rectangle(const Point2& low, const Point2& high) {
  return {low, {high.x(), low.y()}, high, {low.x(), high.y()}};
}

/// One group of holes that the cleaner must merge or cut: overlapping, touching along an
/// edge or at a corner, nested, crossing the hull, touching a hull edge along an edge or at a
/// point. Coordinates are exact multiples of kGrid / 64.
std::vector<Ring> touchingGroup(std::mt19937& rng, const Ring& hull, double size) {
  const double side_high = std::max(2.0, 0.15 * size);
  const auto side = [&] { return std::max(kGrid, snap(uniform(rng, 1.0, side_high))); };
  const Point2 low = {snap(uniform(rng, -0.35, 0.2) * size), snap(uniform(rng, -0.35, 0.2) * size)};
  const Point2 a_high = low + Point2(side(), side());
  const Ring a = rectangle(low, a_high);
  const Point2 b_size(side(), side());
  // A point of hull edge e at dyadic fraction t, and the edge's inward normal.
  const std::size_t e =
      static_cast<std::size_t>(integer(rng, 0, static_cast<int>(hull.size()) - 1));
  const Point2 p = hull[e];
  const Point2 q = hull[(e + 1) % hull.size()];
  const Point2 along = q - p;
  const Point2 inward(-along.y(), along.x());
  const auto onEdge = [&](int sixteenths) { return p + (sixteenths / 16.0) * along; };
  const int t = integer(rng, 2, 12);
  const double depth = integer(rng, 1, 8) / 64.0;
  const double spread = integer(rng, 1, 3) / 16.0;
  switch (integer(rng, 0, 6)) {
    case 0: {  // overlap
      const Point2 shift(snap(uniform(rng, 0.2, 0.8) * (a_high.x() - low.x())),
                         snap(uniform(rng, -0.8, 0.8) * (a_high.y() - low.y())));
      return {a, rectangle(low + shift, low + shift + b_size)};
    }
    case 1: {  // along an edge
      const Point2 b_low(a_high.x(), low.y() + snap(uniform(rng, -0.5, 0.5) * b_size.y()));
      return {a, rectangle(b_low, b_low + b_size)};
    }
    case 2:  // at a corner
      return {a, rectangle(a_high, a_high + b_size)};
    case 3: {  // nested
      const Point2 inset(kGrid, kGrid);
      if (a_high.x() - low.x() < 4.0 * kGrid || a_high.y() - low.y() < 4.0 * kGrid) return {a};
      return {a, rectangle(low + inset, a_high - inset)};
    }
    case 4: {  // crossing the hull
      const Point2 m = onEdge(t + 1);
      const double half = spread;
      return {{m - half * along - depth * inward, m + half * along - depth * inward,
               m + half * along + depth * inward, m - half * along + depth * inward}};
    }
    case 5:  // along a hull edge
      return {
          {onEdge(t), onEdge(t + 2), onEdge(t + 2) + depth * inward, onEdge(t) + depth * inward}};
    default:  // at one point of a hull edge
      return {{onEdge(t + 1), onEdge(t + 2) + depth * inward, onEdge(t) + depth * inward}};
  }
}

/// A grid-snapped star-shaped hull with 1 to 4 groups of touching, overlapping, nested or
/// hull-crossing holes, kept only where validation and cleaning accept them.
void touchingHoles(std::mt19937& rng, bool small, HardMap& map) {
  const double w = map.mission.parameters.wall_distance;
  const double size =
      snap(std::clamp(map.footprint_width_m * uniform(rng, 4.0, 12.0), 15.0 * w, 120.0));
  PolygonWithHoles& polygon = map.mission.polygon;
  do {
    polygon.hull = randomStarRing(rng, {0, 0}, 0.38 * size, 0.5 * size, integer(rng, 4, 10));
    for (Point2& v : polygon.hull) v = {snap(v.x()), snap(v.y())};
  } while (!passesValidator(polygon) || signedArea(polygon.hull) <= 0.0);
  const int groups = small ? 1 : integer(rng, 1, 4);
  for (int attempt = 0, kept = 0; attempt < 20 && kept < groups; ++attempt) {
    PolygonWithHoles candidate = polygon;
    for (Ring hole : touchingGroup(rng, polygon.hull, size)) {
      if (signedArea(hole) > 0.0) std::reverse(hole.begin(), hole.end());
      candidate.holes.push_back(std::move(hole));
    }
    if (!cleaned(candidate)) continue;
    polygon = std::move(candidate);
    ++kept;
  }
  const PolygonWithHoles free_area = *cleaned(polygon);
  const auto endpoint = [&] {
    return pointWhere(rng, polygon.hull, [&](const Point2& p) {
      if (!contains(free_area, p) || distanceToBoundary(p, free_area) < 1e-3) return false;
      for (const Ring& hole : polygon.holes) {
        if (insideRing(p, hole) || distanceToRing(p, hole) < 1e-3) return false;
      }
      return true;
    });
  };
  map.mission.start = endpoint();
  map.mission.goal = endpoint();
}

/// A chart-like ring about `centre`: radius `r` times one plus cosines at ten octaves of
/// frequency (3 to 1536 waves round the ring), each octave's amplitude 0.55 times the one
/// before (noise at every scale, as a surveyed shore has), plus a per-vertex jitter of up to
/// `jitter_m`. The amplitudes sum to under 0.3, so the ring stays star-shaped.
Ring chartRing(std::mt19937& rng, const Point2& centre, double r, int vertices, double jitter_m) {
  std::vector<double> phases;
  for (int octave = 0; octave < 10; ++octave) phases.push_back(uniform(rng, 0.0, 2.0 * M_PI));
  Ring ring;
  for (int i = 0; i < vertices; ++i) {
    const double angle = 2.0 * M_PI * (i + uniform(rng, -0.3, 0.3)) / vertices;
    double radius = 1.0;
    double amplitude = 0.12;
    for (int octave = 0; octave < 10; ++octave) {
      radius += amplitude * std::cos(3.0 * std::pow(2.0, octave) * angle + phases[octave]);
      amplitude *= 0.55;
    }
    radius = r * radius + uniform(rng, -jitter_m, jitter_m);
    ring.push_back(centre + radius * Point2(std::cos(angle), std::sin(angle)));
  }
  return ring;
}

/// random_missions.h's map, start and goal under this generator's parameters.
void star(std::uint64_t seed, HardMap& map) {
  const RandomMission random = randomMission(seed, 15);
  map.mission.polygon = random.mission.polygon;
  map.mission.start = random.mission.start;
  map.mission.goal = random.mission.goal;
}

/// Up to `islands` noisy islands 2 to 8 m across (lakeChart's) about centres that
/// `centre_ok` takes, at least 1 m from the shore and from each other; a lake too crowded
/// for them all gets fewer.
template <typename CentreOk>
std::vector<Ring> chartIslands(std::mt19937& rng, const Ring& shore, int islands,
                               CentreOk centre_ok) {
  std::vector<Ring> placed;
  for (int i = 0, attempts = 0; i < islands && attempts < 100 * islands; ++attempts) {
    const Point2 centre = pointWhere(rng, shore, centre_ok);
    const Ring island = noisyRing(rng, centre, uniform(rng, 1.0, 4.0),
                                  integer(rng, HardMapGenerator::kLakeChartIslandVertices.first,
                                          HardMapGenerator::kLakeChartIslandVertices.second));
    if (gapOf(island, shore, placed) <= 1.0) continue;
    placed.push_back(island);
    ++i;
  }
  return placed;
}

/// A chart's map before its polygon: the shoreline family, default parameters and the
/// footprint they give.
HardMap defaultParameterMap(std::uint64_t seed) {
  HardMap map;
  map.family = MapFamily::kShoreline;
  map.seed = seed;
  const PlannerParameters& p = map.mission.parameters;
  map.footprint_width_m = 2.0 * p.sensor_distance * std::tan(0.5 * p.lateral_fov);
  map.footprint_length_m = 2.0 * p.sensor_distance * std::tan(0.5 * p.onward_fov);
  return map;
}

/// Sets a chart's polygon (`shore` counter-clockwise, `islands` counter-clockwise, turned
/// into holes) and draws its start and goal in the free area.
void setPolygon(std::mt19937& rng, Ring shore, std::vector<Ring> islands, HardMap& map) {
  PolygonWithHoles& polygon = map.mission.polygon;
  polygon.hull = std::move(shore);
  for (Ring& island : islands) {
    std::reverse(island.begin(), island.end());
    polygon.holes.push_back(std::move(island));
  }
  map.mission.start = freePoint(rng, polygon);
  map.mission.goal = freePoint(rng, polygon);
}

}  // namespace

HardMap HardMapGenerator::lakeChart(std::uint64_t seed, int shore_vertices, int islands) {
  std::seed_seq sequence{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                         static_cast<std::uint32_t>(shore_vertices),
                         static_cast<std::uint32_t>(islands)};
  std::mt19937 rng(sequence);
  HardMap map = defaultParameterMap(seed);
  const double size = kLakeChartSize;
  const Ring star = chartRing(rng, {0, 0}, 0.5 * size, shore_vertices, 0.2);
  const Ring shore = warpedShore(rng, star, size, {0.04, 0.1}, {0.15, 0.3});
  setPolygon(rng, shore,
             chartIslands(rng, shore, islands,
                          [&](const Point2& p) {
                            return insideRing(p, shore) && distanceToRing(p, shore) > 10.0;
                          }),
             map);
  return map;
}

HardMap HardMapGenerator::roughShore(std::uint64_t seed, int shore_vertices, int islands) {
  std::seed_seq sequence{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                         static_cast<std::uint32_t>(shore_vertices),
                         static_cast<std::uint32_t>(islands), 0x726f7567u};
  std::mt19937 rng(sequence);
  HardMap map = defaultParameterMap(seed);
  Ring shore;
  for (int i = 0; i < shore_vertices; ++i) {
    const double angle = 2.0 * M_PI * i / shore_vertices;
    const double radius = kRoughShoreRadius + uniform(rng, -kRoughShoreNoise, kRoughShoreNoise);
    shore.push_back(radius * Point2(std::cos(angle), std::sin(angle)));
  }
  setPolygon(rng, shore,
             chartIslands(rng, shore, islands,
                          [](const Point2& p) {
                            return p.norm() < kRoughShoreRadius - kRoughShoreNoise - 10.0;
                          }),
             map);
  return map;
}

HardMap HardMapGenerator::archipelago(std::uint64_t seed, int islands) {
  std::seed_seq sequence{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                         static_cast<std::uint32_t>(islands), 0x617263u};
  std::mt19937 rng(sequence);
  HardMap map = defaultParameterMap(seed);
  const double size = kArchipelagoSize;
  const Ring shore = rectangle({0.0, 0.0}, {size, size});
  // Centres drawn on a grid of buckets one spacing wide, so that each draw checks only its
  // neighbours' centres.
  const double spacing = kArchipelagoSpacing;
  const int buckets = static_cast<int>(std::ceil(size / spacing));
  std::vector<std::vector<Point2>> bucket(static_cast<std::size_t>(buckets * buckets));
  auto bucketOf = [&](double v) {
    return std::clamp(static_cast<int>(v / spacing), 0, buckets - 1);
  };
  auto farFromOthers = [&](const Point2& c) {
    for (int bx = bucketOf(c.x()) - 1; bx <= bucketOf(c.x()) + 1; ++bx) {
      for (int by = bucketOf(c.y()) - 1; by <= bucketOf(c.y()) + 1; ++by) {
        if (bx < 0 || by < 0 || bx >= buckets || by >= buckets) continue;
        for (const Point2& other : bucket[static_cast<std::size_t>(bx * buckets + by)]) {
          if ((other - c).norm() < spacing) return false;
        }
      }
    }
    return true;
  };
  std::vector<Ring> placed;
  for (int i = 0, attempts = 0; i < islands && attempts < 100 * islands; ++attempts) {
    const Point2 centre(uniform(rng, spacing, size - spacing),
                        uniform(rng, spacing, size - spacing));
    if (!farFromOthers(centre)) continue;
    bucket[static_cast<std::size_t>(bucketOf(centre.x()) * buckets + bucketOf(centre.y()))]
        .push_back(centre);
    const int vertices =
        integer(rng, kArchipelagoIslandVertices.first, kArchipelagoIslandVertices.second);
    const double radius =
        uniform(rng, kArchipelagoIslandRadius.first, kArchipelagoIslandRadius.second);
    // Star-shaped about the centre: vertices at increasing angles, each at 0.5 to 1 times the
    // radius (the largest at exactly the radius).
    std::vector<double> angles;
    for (int k = 0; k < vertices; ++k) angles.push_back((k + uniform(rng, -0.3, 0.3)) / vertices);
    Ring island;
    for (int k = 0; k < vertices; ++k) {
      const double r = k == 0 ? radius : radius * uniform(rng, 0.5, 1.0);
      const double angle = 2.0 * M_PI * angles[static_cast<std::size_t>(k)];
      island.push_back(centre + r * Point2(std::cos(angle), std::sin(angle)));
    }
    placed.push_back(std::move(island));
    ++i;
  }
  setPolygon(rng, shore, std::move(placed), map);
  return map;
}

HardMap HardMapGenerator::generate(std::uint64_t seed) const {
  std::seed_seq sequence{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                         static_cast<std::uint32_t>(family_)};
  std::mt19937 rng(sequence);
  HardMap map;
  map.family = family_;
  map.seed = seed;
  drawParameters(rng, map);
  const bool small = size_ == MapSize::kFuzz;
  switch (family_) {
    case MapFamily::kComb:
      comb(rng, small, map);
      break;
    case MapFamily::kSpiral:
      spiral(rng, small, map);
      break;
    case MapFamily::kRooms:
      rooms(rng, map);
      break;
    case MapFamily::kShoreline:
      shoreline(rng, small, map);
      break;
    case MapFamily::kTouchingHoles:
      touchingHoles(rng, small, map);
      break;
    case MapFamily::kStar:
      star(seed, map);
      break;
  }
  return map;
}

std::vector<MapFamily> HardMapGenerator::families() {
  return {MapFamily::kComb,      MapFamily::kSpiral,        MapFamily::kRooms,
          MapFamily::kShoreline, MapFamily::kTouchingHoles, MapFamily::kStar};
}

std::string HardMapGenerator::name(MapFamily family) {
  switch (family) {
    case MapFamily::kComb:
      return "comb";
    case MapFamily::kSpiral:
      return "spiral";
    case MapFamily::kRooms:
      return "rooms";
    case MapFamily::kShoreline:
      return "shoreline";
    case MapFamily::kTouchingHoles:
      return "touching_holes";
    case MapFamily::kStar:
      return "star";
  }
  return "";
}

std::optional<MapFamily> HardMapGenerator::fromName(const std::string& name) {
  for (MapFamily family : families()) {
    if (HardMapGenerator::name(family) == name) return family;
  }
  return std::nullopt;
}

std::optional<std::vector<MapFamily>> HardMapGenerator::fromNames(const std::string& names) {
  std::vector<MapFamily> result;
  std::istringstream list(names);
  std::string name;
  while (std::getline(list, name, ',')) {
    const std::optional<MapFamily> family = fromName(name);
    if (!family) return std::nullopt;
    result.push_back(*family);
  }
  if (result.empty()) return std::nullopt;
  return result;
}

}  // namespace testing
}  // namespace kinematic_coverage::core
