#include "polygon_coverage_ros_bridge/validation/free_area_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"

namespace kinematic_coverage::core {
namespace {

Ring rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

std::string errorOf(const PolygonWithHoles& raw, const std::vector<NamedEndpoint>& endpoints) {
  try {
    FreeAreaBuilder().build(raw, endpoints);
  } catch (const InvalidInputError& error) {
    return error.what();
  }
  return "";
}

TEST(FreeAreaBuilder, ValidatesThenCleans) {
  // Two overlapping holes: valid input, merged by the cleaner with a warning.
  const PolygonWithHoles raw{rectangle(0, 0, 20, 10),
                             {rectangle(4, 4, 8, 6), rectangle(7, 3, 10, 7)}};
  const BuiltFreeArea built = FreeAreaBuilder().build(raw, {{"start", {1, 1}}, {"goal", {19, 9}}});
  ASSERT_EQ(built.cleaned.free_area.holes.size(), 1u);
  EXPECT_EQ(built.cleaned.warnings.size(), 1u);
  EXPECT_NEAR(area(built.cleaned.free_area), 200.0 - 8.0 - 12.0 + 2.0, 1e-9);
  EXPECT_GE(built.validate_s, 0.0);
  EXPECT_GE(built.clean_s, 0.0);
}

TEST(FreeAreaBuilder, RejectsInvalidPolygonsAndEndpointsBeforeCleaning) {
  const PolygonWithHoles bow_tie{{{0, 0}, {10, 10}, {10, 0}, {0, 10}}, {}};
  EXPECT_NE(errorOf(bow_tie, {}), "");
  const PolygonWithHoles room{rectangle(0, 0, 20, 10), {rectangle(4, 4, 8, 6)}};
  EXPECT_EQ(errorOf(room, {{"start", {5, 5}}}), "start (5, 5) lies inside hole 0");
  EXPECT_NE(errorOf(room, {{"goal", {std::nan(""), 1}}}), "");
  // Holes splitting the free area are the cleaner's error, after validation passed.
  const PolygonWithHoles split{rectangle(0, 0, 20, 10), {rectangle(8, -1, 12, 11)}};
  EXPECT_NE(errorOf(split, {}), "");
}

/// A lake 120 m across whose shore has 12 000 vertices, a saw of 0.2 m teeth (6 000 reflex
/// vertices), and a 4 m island with a bay 0.3 m deep cut into it.
PolygonWithHoles sawShoreLake() {
  PolygonWithHoles lake;
  const int n = 12000;
  for (int i = 0; i < n; ++i) {
    const double angle = 2.0 * M_PI * i / n;
    const double radius = i % 2 == 0 ? 60.2 : 60.0;
    lake.hull.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
  }
  // Clockwise, with the bay between x = 0.85 and 1.15 at the island's top (y = 2).
  lake.holes.push_back({{-2, -2}, {-2, 2}, {0.85, 2}, {1.0, 1.7}, {1.15, 2}, {2, 2}, {2, -2}});
  return lake;
}

TEST(FreeAreaBuilder, SimplifiesAnAreaWithAHugeRingInwardWithAWarning) {
  const PolygonWithHoles lake = sawShoreLake();
  ASSERT_GT(lake.hull.size(), kMaxExactRingVertices);
  const BuiltFreeArea exact = FreeAreaBuilder().build(lake);
  EXPECT_TRUE(exact.cleaned.warnings.empty());
  EXPECT_EQ(exact.cleaned.free_area.hull.size(), lake.hull.size());

  const double tolerance = 0.5;
  const BuiltFreeArea built = FreeAreaBuilder(tolerance).build(lake, {{"start", {10, 10}}});
  const PolygonWithHoles& simplified = built.cleaned.free_area;
  EXPECT_LE(simplified.hull.size(), kMaxExactRingVertices);
  ASSERT_EQ(built.cleaned.warnings.size(), 1u);
  EXPECT_NE(built.cleaned.warnings[0].find("simplified inward within 0.5 m"), std::string::npos)
      << built.cleaned.warnings[0];
  // Inward and within the tolerance: the area shrinks by at most the tolerance along the
  // boundary, and every given vertex lies within the tolerance of the simplified boundary.
  const double given_up = area(lake) - area(simplified);
  EXPECT_GT(given_up, 0.0);
  EXPECT_LT(given_up, tolerance * 2.0 * M_PI * 60.2);
  for (const Point2& p : lake.hull) EXPECT_LE(distanceToRing(p, simplified.hull), tolerance + 1e-9);
  ASSERT_EQ(simplified.holes.size(), 1u);
  EXPECT_TRUE(insideRing({1.0, 1.9}, simplified.holes[0]));  // the bay, 0.3 m deep, is closed
}

/// A start in the island's bay would end inside the grown island: the area is then left as it
/// is (and planned exactly), rather than the user's start blamed for lying in a hole.
TEST(FreeAreaBuilder, LeavesTheAreaExactWhereSimplifyingWouldSwallowAnEndpoint) {
  const PolygonWithHoles lake = sawShoreLake();
  const BuiltFreeArea built = FreeAreaBuilder(0.5).build(lake, {{"start", {1.0, 1.95}}});
  EXPECT_TRUE(built.cleaned.warnings.empty());
  EXPECT_EQ(built.cleaned.free_area.hull.size(), lake.hull.size());
}

}  // namespace
}  // namespace kinematic_coverage::core
