#include "polygon_coverage_ros_bridge/validation/free_area_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

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

}  // namespace
}  // namespace kinematic_coverage::core
