#include "polygon_coverage_ros_bridge/geometry/boundary_simplification.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// Slack for rounding in the distance checks (m).
constexpr double kSlack = 1e-9;

/// A ring around `centre` of radius `radius` with `vertices` vertices, its radius varied by
/// a few slow waves (bays and headlands) plus uniform jitter of `jitter` m: a shore or an
/// island of a chart. Counter-clockwise.
Ring noisyRing(std::mt19937& rng, const Point2& centre, double radius, int vertices,
               double jitter) {
  std::uniform_real_distribution<double> phase(0.0, 2.0 * M_PI);
  std::uniform_real_distribution<double> noise(-jitter, jitter);
  const double p1 = phase(rng);
  const double p2 = phase(rng);
  Ring ring;
  for (int i = 0; i < vertices; ++i) {
    const double angle = 2.0 * M_PI * i / vertices;
    const double r =
        radius * (1.0 + 0.12 * std::sin(3 * angle + p1) + 0.05 * std::sin(11 * angle + p2)) +
        noise(rng);
    ring.push_back(centre + r * Point2(std::cos(angle), std::sin(angle)));
  }
  return ring;
}

/// A chart-like lake: a noisy shore of `shore_vertices` about 100 m across and `islands`
/// noisy islands of 30 vertices inside it, apart from the shore and from each other.
PolygonWithHoles noisyLake(std::uint32_t seed, int shore_vertices, int islands, double jitter) {
  std::mt19937 rng(seed);
  PolygonWithHoles lake;
  lake.hull = noisyRing(rng, {0, 0}, 50.0, shore_vertices, jitter);
  std::uniform_real_distribution<double> coordinate(-25.0, 25.0);
  std::vector<Point2> centres;
  for (int attempt = 0; static_cast<int>(lake.holes.size()) < islands && attempt < 1000;
       ++attempt) {
    const Point2 centre(coordinate(rng), coordinate(rng));
    const bool apart = std::all_of(centres.begin(), centres.end(),
                                   [&](const Point2& c) { return (c - centre).norm() > 10.0; });
    if (!apart) continue;
    centres.push_back(centre);
    Ring island = noisyRing(rng, centre, 3.0, 30, jitter);
    std::reverse(island.begin(), island.end());
    lake.holes.push_back(std::move(island));
  }
  return lake;
}

/// True when the closed segments [p, q] and [r, t] cross properly.
bool crossProperly(const Point2& p, const Point2& q, const Point2& r, const Point2& t) {
  return cross(p, q, r) * cross(p, q, t) < 0.0 && cross(r, t, p) * cross(r, t, q) < 0.0;
}

std::vector<std::pair<Point2, Point2>> edgesOf(const PolygonWithHoles& area) {
  std::vector<std::pair<Point2, Point2>> edges;
  std::vector<const Ring*> rings = {&area.hull};
  for (const Ring& hole : area.holes) rings.push_back(&hole);
  for (const Ring* ring : rings) {
    for (std::size_t i = 0; i < ring->size(); ++i) {
      edges.emplace_back((*ring)[i], (*ring)[(i + 1) % ring->size()]);
    }
  }
  return edges;
}

/// The properties of an inward simplification of `given` within `tolerance`.
void expectInwardWithin(const PolygonWithHoles& given, const PolygonWithHoles& simplified,
                        double tolerance) {
  ASSERT_EQ(simplified.holes.size(), given.holes.size());
  std::vector<const Ring*> before = {&given.hull};
  std::vector<const Ring*> after = {&simplified.hull};
  for (std::size_t h = 0; h < given.holes.size(); ++h) {
    before.push_back(&given.holes[h]);
    after.push_back(&simplified.holes[h]);
  }
  for (std::size_t r = 0; r < before.size(); ++r) {
    const Ring& original = *before[r];
    const Ring& kept = *after[r];
    SCOPED_TRACE(r == 0 ? std::string("hull") : "hole " + std::to_string(r - 1));
    ASSERT_GE(kept.size(), 3u);
    // The same orientation, a subset of the vertices in their order, and every given
    // vertex within the tolerance of the simplified ring.
    EXPECT_EQ(signedArea(kept) > 0.0, signedArea(original) > 0.0);
    std::size_t at = 0;
    for (const Point2& p : kept) {
      while (at < original.size() && original[at] != p) ++at;
      ASSERT_LT(at, original.size()) << "vertex " << p.transpose() << " is not a given one";
    }
    for (const Point2& p : original) EXPECT_LE(distanceToRing(p, kept), tolerance + kSlack);
    // The hull shrinks and the holes grow.
    if (r == 0) {
      EXPECT_LE(std::abs(signedArea(kept)), std::abs(signedArea(original)) + kSlack);
    } else {
      EXPECT_GE(std::abs(signedArea(kept)), std::abs(signedArea(original)) - kSlack);
    }
  }
  // Inside the given area, and still simple with its rings apart.
  const auto edges = edgesOf(simplified);
  for (const auto& [a, b] : edges) {
    EXPECT_TRUE(segmentInside(given, a, b, 1e-9)) << a.transpose() << " to " << b.transpose();
  }
  for (std::size_t i = 0; i < edges.size(); ++i) {
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      ASSERT_FALSE(crossProperly(edges[i].first, edges[i].second, edges[j].first, edges[j].second))
          << "edges " << i << " and " << j << " cross";
    }
  }
}

TEST(BoundarySimplification, NoisyLakesKeepTheirShapeInAFractionOfTheVertices) {
  for (std::uint32_t seed = 1; seed <= 3; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const PolygonWithHoles lake = noisyLake(seed, 1500, 8, 0.1);
    const double tolerance = 0.3;
    const PolygonWithHoles simplified = BoundarySimplification(tolerance).simplify(lake);
    expectInwardWithin(lake, simplified, tolerance);
    // The jitter (0.1 m) is below the tolerance: most of the shore's vertices go.
    EXPECT_LT(BoundarySimplification::vertexCount(simplified),
              BoundarySimplification::vertexCount(lake) / 3);
    // The area lost is a thin rim along the boundary, within the tolerance of it.
    double boundary_length = 0.0;
    for (const auto& [a, b] : edgesOf(lake)) boundary_length += (b - a).norm();
    EXPECT_GT(area(simplified), area(lake) - tolerance * boundary_length);
  }
}

TEST(BoundarySimplification, ZeroToleranceDropsOnlyStraightVertices) {
  const PolygonWithHoles square = {{{0, 0}, {5, 0}, {10, 0}, {10, 10}, {0, 10}},
                                   {{{4, 4}, {4, 6}, {5, 6}, {6, 6}, {6, 4}}}};
  const PolygonWithHoles simplified = BoundarySimplification(0.0).simplify(square);
  EXPECT_EQ(simplified.hull, Ring({{0, 0}, {10, 0}, {10, 10}, {0, 10}}));
  EXPECT_EQ(simplified.holes.front(), Ring({{4, 4}, {4, 6}, {6, 6}, {6, 4}}));

  std::mt19937 rng(5);
  PolygonWithHoles noisy;
  noisy.hull = noisyRing(rng, {0, 0}, 20.0, 300, 0.2);
  const PolygonWithHoles same = BoundarySimplification(0.0).simplify(noisy);
  expectInwardWithin(noisy, same, 0.0);
}

TEST(BoundarySimplification, ANarrowInletLongerThanTheToleranceStays) {
  // A 0.1 m wide, 5 m long inlet of the free area into the wall: cutting it off would move
  // the boundary 5 m, so its far end stays.
  const PolygonWithHoles area = {
      {{0, 0}, {10, 0}, {10, 10}, {5.05, 10}, {5.05, 15}, {4.95, 15}, {4.95, 10}, {0, 10}}, {}};
  const PolygonWithHoles simplified = BoundarySimplification(0.5).simplify(area);
  expectInwardWithin(area, simplified, 0.5);
  const bool reaches_the_end = std::any_of(simplified.hull.begin(), simplified.hull.end(),
                                           [](const Point2& p) { return p.y() > 14.5; });
  EXPECT_TRUE(reaches_the_end);
}

TEST(BoundarySimplification, SmallIslandsAndTouchingRingsAreKept) {
  // A 0.2 m triangular island (smaller than the tolerance), and a diamond hole touching the
  // hull at a vertex between two small bumps of the hull.
  const PolygonWithHoles area = {
      {{0, 0}, {10, 0}, {10, 10}, {5.5, 10.05}, {5, 10}, {4.5, 10.05}, {0, 10}},
      {{{5, 5}, {5.1, 5.2}, {5.2, 5}}, {{5, 10}, {6, 9}, {5, 8}, {4, 9}}}};
  const PolygonWithHoles simplified = BoundarySimplification(1.0).simplify(area);
  expectInwardWithin(area, simplified, 1.0);
  EXPECT_EQ(simplified.holes[0].size(), 3u);
  EXPECT_EQ(simplified.holes[1].size(), 4u);
  EXPECT_NE(std::find(simplified.hull.begin(), simplified.hull.end(), Point2(5, 10)),
            simplified.hull.end());
}

TEST(BoundarySimplification, RandomStarsStayInsideAndSimple) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> tolerance(0.0, 2.0);
  for (int map = 0; map < 30; ++map) {
    SCOPED_TRACE("map " + std::to_string(map));
    PolygonWithHoles area;
    area.hull = noisyRing(rng, {0, 0}, 30.0, 200, 1.5);
    Ring hole = noisyRing(rng, {3, -2}, 6.0, 60, 1.0);
    std::reverse(hole.begin(), hole.end());
    area.holes.push_back(hole);
    const double t = tolerance(rng);
    expectInwardWithin(area, BoundarySimplification(t).simplify(area), t);
  }
}

TEST(BoundarySimplification, RejectsANegativeOrNonFiniteTolerance) {
  EXPECT_THROW(BoundarySimplification(-0.1), InvalidInputError);
  EXPECT_THROW(BoundarySimplification(std::nan("")), InvalidInputError);
  const double infinite = std::numeric_limits<double>::infinity();
  EXPECT_THROW(BoundarySimplification{infinite}, InvalidInputError);
}

}  // namespace
}  // namespace kinematic_coverage::core
