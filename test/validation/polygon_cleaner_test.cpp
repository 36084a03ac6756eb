#include "polygon_coverage_ros_bridge/validation/polygon_cleaner.h"

#include <gtest/gtest.h>

#include <random>
#include <string>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/validation/free_area_builder.h"
#include "polygon_coverage_ros_bridge/validation/polygon_validator.h"
#include "test/support/random_polygons.h"

namespace kinematic_coverage::core {
namespace {

Ring square(double x0, double y0, double size) {
  return {{x0, y0}, {x0 + size, y0}, {x0 + size, y0 + size}, {x0, y0 + size}};
}

Ring rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

/// Cleans after validating, as every entry point does.
CleanedPolygon clean(const PolygonWithHoles& raw) { return FreeAreaBuilder().build(raw).cleaned; }

std::string cleaningError(const PolygonWithHoles& raw) {
  try {
    clean(raw);
  } catch (const InvalidInputError& error) {
    return error.what();
  }
  return "";
}

/// Every output ring simple, the hull counter-clockwise and the holes clockwise.
void expectWellFormed(const PolygonWithHoles& free_area) {
  const PolygonValidator validator;
  EXPECT_NO_THROW(validator.validateRing(free_area.hull, "hull"));
  EXPECT_GT(signedArea(free_area.hull), 0.0);
  for (const Ring& hole : free_area.holes) {
    EXPECT_NO_THROW(validator.validateRing(hole, "hole"));
    EXPECT_LT(signedArea(hole), 0.0);
  }
}

TEST(PolygonCleaner, HolesThatLeaveOnlyASliverFreeAreInvalidInput) {
  // Found by planner_fuzzer: two holes cover a thin triangle but for 1.8e-15 m^2, and the
  // route stage, for which that is a line, failed on the "valid" free area.
  const std::string error = cleaningError({{{-5, -5},
                                            {-4.999999999992768, 13.947368431836509},
                                            {-3.441543287949205, 33.12523863956347}},
                                           {{{14.340920738194825, 16.11604005098343},
                                             {-4.9999999999999645, -5},
                                             {-4.999999999999858, 34.998779296875}},
                                            {{-4.999999996309658, 10.501375971647917},
                                             {-4.965576520716009, -4.972490270619115},
                                             {-4.9763003491785005, -4.940231984954153}}}});
  EXPECT_EQ(error.rfind("after cleaning, the hull is a sliver", 0), 0u) << error;
}

TEST(PolygonCleaner, LeavesACleanPolygonAloneButOrientsIt) {
  PolygonWithHoles raw{square(0, 0, 30), {square(8, 8, 4)}};
  std::reverse(raw.hull.begin(), raw.hull.end());
  const CleanedPolygon cleaned = clean(raw);
  EXPECT_TRUE(cleaned.warnings.empty());
  expectWellFormed(cleaned.free_area);
  EXPECT_EQ(cleaned.free_area.holes.size(), 1u);
  EXPECT_EQ(cleaned.free_area.hull.size(), 4u);
  EXPECT_DOUBLE_EQ(area(cleaned.free_area), 900.0 - 16.0);
}

TEST(PolygonCleaner, DropsDuplicateConsecutiveVertices) {
  const PolygonWithHoles raw{{{0, 0}, {10, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}},
                             {{{2, 2}, {2, 2}, {4, 2}, {4, 4}, {2, 4}}}};
  const CleanedPolygon cleaned = clean(raw);
  ASSERT_EQ(cleaned.warnings.size(), 2u);
  EXPECT_EQ(cleaned.warnings[0], "hull: 2 duplicate consecutive vertices dropped");
  EXPECT_EQ(cleaned.warnings[1], "hole 0: 1 duplicate consecutive vertex dropped");
  EXPECT_EQ(cleaned.free_area.hull.size(), 4u);
  ASSERT_EQ(cleaned.free_area.holes.size(), 1u);
  EXPECT_EQ(cleaned.free_area.holes[0].size(), 4u);
  EXPECT_DOUBLE_EQ(area(cleaned.free_area), 96.0);
}

TEST(PolygonCleaner, MergesOverlappingHoles) {
  const PolygonWithHoles raw{square(0, 0, 30),
                             {square(5, 5, 4), square(20, 20, 2), square(7, 7, 4)}};
  const CleanedPolygon cleaned = clean(raw);
  ASSERT_EQ(cleaned.warnings.size(), 1u);
  EXPECT_EQ(cleaned.warnings[0], "hole 0 and hole 2 overlap: merged");
  EXPECT_EQ(cleaned.free_area.holes.size(), 2u);
  expectWellFormed(cleaned.free_area);
  EXPECT_DOUBLE_EQ(area(cleaned.free_area), 900.0 - (16.0 + 16.0 - 4.0) - 4.0);
}

TEST(PolygonCleaner, MergesHolesTouchingAlongAnEdge) {
  const PolygonWithHoles raw{square(0, 0, 30), {square(5, 5, 4), square(9, 6, 3)}};
  const CleanedPolygon cleaned = clean(raw);
  ASSERT_EQ(cleaned.warnings.size(), 1u);
  EXPECT_EQ(cleaned.warnings[0], "hole 0 and hole 1 touch along an edge: merged");
  EXPECT_EQ(cleaned.free_area.holes.size(), 1u);
  expectWellFormed(cleaned.free_area);
  EXPECT_DOUBLE_EQ(area(cleaned.free_area), 900.0 - 16.0 - 9.0);
}

TEST(PolygonCleaner, MergesAHoleInsideAnother) {
  const PolygonWithHoles raw{square(0, 0, 30), {square(6, 6, 1), square(5, 5, 4)}};
  const CleanedPolygon cleaned = clean(raw);
  ASSERT_EQ(cleaned.warnings.size(), 1u);
  EXPECT_EQ(cleaned.warnings[0], "hole 0 lies inside hole 1: merged");
  EXPECT_EQ(cleaned.free_area.holes.size(), 1u);
  EXPECT_DOUBLE_EQ(area(cleaned.free_area), 900.0 - 16.0);
}

TEST(PolygonCleaner, CutsOffTheOutsidePartOfAHoleCrossingTheHull) {
  const PolygonWithHoles raw{square(0, 0, 30), {square(25, 10, 10), square(8, 8, 2)}};
  const CleanedPolygon cleaned = clean(raw);
  ASSERT_EQ(cleaned.warnings.size(), 1u);
  EXPECT_EQ(cleaned.warnings[0],
            "hole 0 crosses the hull: its part outside the hull is cut off and the hull is "
            "cut back");
  EXPECT_EQ(cleaned.free_area.holes.size(), 1u);
  expectWellFormed(cleaned.free_area);
  EXPECT_DOUBLE_EQ(area(cleaned.free_area), 900.0 - 50.0 - 4.0);
  EXPECT_DOUBLE_EQ(signedArea(cleaned.free_area.hull), 900.0 - 50.0);
}

TEST(PolygonCleaner, CutsTheHullBackAtAHoleTouchingItAlongAnEdge) {
  const PolygonWithHoles raw{square(0, 0, 30), {rectangle(0, 10, 5, 15)}};
  const CleanedPolygon cleaned = clean(raw);
  ASSERT_EQ(cleaned.warnings.size(), 1u);
  EXPECT_EQ(cleaned.warnings[0], "hole 0 touches the hull along an edge: the hull is cut back");
  EXPECT_TRUE(cleaned.free_area.holes.empty());
  expectWellFormed(cleaned.free_area);
  EXPECT_DOUBLE_EQ(area(cleaned.free_area), 900.0 - 25.0);
}

TEST(PolygonCleaner, KeepsAHoleTouchingTheHullAtOnePointAsASimpleHole) {
  const Ring diamond = {{0, 15}, {5, 10}, {10, 15}, {5, 20}};
  const CleanedPolygon cleaned = clean({square(0, 0, 30), {diamond}});
  EXPECT_TRUE(cleaned.warnings.empty());
  expectWellFormed(cleaned.free_area);
  EXPECT_DOUBLE_EQ(signedArea(cleaned.free_area.hull), 900.0);
  EXPECT_EQ(cleaned.free_area.holes.size(), 1u);
  EXPECT_DOUBLE_EQ(area(cleaned.free_area), 900.0 - 50.0);
}

TEST(PolygonCleaner, KeepsHolesTouchingAtOnePointAsSimpleRings) {
  const CleanedPolygon cleaned = clean({square(0, 0, 30), {square(5, 5, 5), square(10, 10, 5)}});
  EXPECT_TRUE(cleaned.warnings.empty());
  expectWellFormed(cleaned.free_area);
  EXPECT_EQ(cleaned.free_area.holes.size(), 2u);
  EXPECT_DOUBLE_EQ(area(cleaned.free_area), 900.0 - 50.0);
}

TEST(PolygonCleaner, RejectsHolesSplittingTheFreeArea) {
  const std::string across = cleaningError({square(0, 0, 30), {rectangle(-1, 10, 31, 12)}});
  EXPECT_EQ(across.rfind("the holes split the free area into 2 disconnected parts", 0), 0u)
      << across;
  // A diamond touching two opposite sides: the parts meet at single points only.
  const Ring diamond = {{15, 0}, {25, 15}, {15, 30}, {5, 15}};
  const std::string pinched = cleaningError({square(0, 0, 30), {diamond}});
  EXPECT_EQ(pinched.rfind("the holes split the free area into 2 disconnected parts", 0), 0u)
      << pinched;
  // Two L-shaped holes touching each other at two points enclose a pocket.
  const Ring lower = {{5, 5}, {15, 5}, {15, 10}, {7, 10}, {7, 15}, {5, 15}};
  const Ring upper = {{15, 10}, {17, 10}, {17, 17}, {7, 17}, {7, 15}, {15, 15}};
  const std::string touching = cleaningError({square(0, 0, 30), {lower, upper}});
  EXPECT_EQ(touching.rfind("the holes split the free area into 2 disconnected parts", 0), 0u)
      << touching;
  // Four bars enclosing a pocket.
  const std::string pocket = cleaningError({square(0, 0, 30),
                                            {rectangle(5, 5, 25, 7), rectangle(5, 23, 25, 25),
                                             rectangle(5, 5, 7, 25), rectangle(23, 5, 25, 25)}});
  EXPECT_EQ(pocket.rfind("the holes split the free area into 2 disconnected parts", 0), 0u)
      << pocket;
}

TEST(PolygonCleaner, RejectsHolesCoveringTheHull) {
  EXPECT_EQ(cleaningError({square(0, 0, 10), {square(-1, -1, 12)}}),
            "the holes cover the whole hull: the free area is empty");
  EXPECT_EQ(cleaningError({square(0, 0, 10), {rectangle(-1, -1, 5, 11), rectangle(5, -1, 11, 11)}}),
            "the holes cover the whole hull: the free area is empty");
}

TEST(PolygonCleaner, FreeAreaMatchesTheRawPolygonOnRandomOverlappingHoles) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> coordinate(-40.0, 40.0);
  std::uniform_real_distribution<double> radius(3.0, 15.0);
  std::uniform_int_distribution<int> hole_count(0, 12);
  std::uniform_real_distribution<double> sample(-60.0, 60.0);
  int cleaned_maps = 0, rejected_maps = 0, merged = 0, crossing = 0;
  for (int trial = 0; trial < 150; ++trial) {
    PolygonWithHoles raw;
    raw.hull = testing::randomStarRing(rng, {0, 0}, 35.0, 50.0, 10);
    const int holes = hole_count(rng);
    for (int h = 0; h < holes; ++h) {
      const double r = radius(rng);
      raw.holes.push_back(
          testing::randomStarRing(rng, {coordinate(rng), coordinate(rng)}, 0.5 * r, r, 6));
    }
    CleanedPolygon cleaned;
    try {
      cleaned = clean(raw);
    } catch (const InvalidInputError& error) {
      const std::string message = error.what();
      const bool expected = message.find("disconnected") != std::string::npos ||
                            message.find("entirely outside the hull") != std::string::npos ||
                            message.find("free area is empty") != std::string::npos;
      EXPECT_TRUE(expected) << message;
      ++rejected_maps;
      continue;
    }
    ++cleaned_maps;
    for (const std::string& warning : cleaned.warnings) {
      merged += warning.find("merged") != std::string::npos;
      crossing += warning.find("crosses the hull") != std::string::npos;
    }
    expectWellFormed(cleaned.free_area);
    for (int s = 0; s < 500; ++s) {
      const Point2 p(sample(rng), sample(rng));
      if (distanceToBoundary(p, raw) < 1e-6) continue;
      bool free = insideRing(p, raw.hull);
      for (const Ring& hole : raw.holes) free = free && !insideRing(p, hole);
      EXPECT_EQ(contains(cleaned.free_area, p), free)
          << "trial " << trial << " point (" << p.x() << ", " << p.y() << ")";
    }
  }
  EXPECT_GT(cleaned_maps, 50);
  EXPECT_GT(rejected_maps, 0);
  EXPECT_GT(merged, 20);
  EXPECT_GT(crossing, 10);
}

}  // namespace
}  // namespace kinematic_coverage::core
