#include "polygon_coverage_ros_bridge/geometry/region_intersection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

PolygonWithHoles box(double x0, double y0, double x1, double y1) {
  return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}};
}

TEST(UnionOfAreasTest, OverlappingAndDisjointAreas) {
  const std::vector<PolygonWithHoles> row = {box(0, 0, 1, 1), box(0.75, 0, 1.75, 1),
                                             box(1.5, 0, 2.5, 1), box(5, 5, 6, 6)};
  const std::vector<PolygonWithHoles> united = unionOfAreas(row);
  ASSERT_EQ(united.size(), 2u);
  EXPECT_NEAR(area(united), 3.5, 1e-12);
  for (const PolygonWithHoles& part : united) {
    EXPECT_GT(signedArea(part.hull), 0.0);
    EXPECT_TRUE(part.holes.empty());
  }
}

TEST(UnionOfAreasTest, AFrameOfFourStripsEnclosesAHole) {
  const std::vector<PolygonWithHoles> frame = {box(0, 0, 4, 1), box(3, 0, 4, 4), box(0, 3, 4, 4),
                                               box(0, 0, 1, 4)};
  const std::vector<PolygonWithHoles> united = unionOfAreas(frame);
  ASSERT_EQ(united.size(), 1u);
  ASSERT_EQ(united.front().holes.size(), 1u);
  EXPECT_LT(signedArea(united.front().holes.front()), 0.0);
  EXPECT_NEAR(area(united), 12.0, 1e-12);
}

TEST(UnionOfAreasTest, ManyRandomRectanglesCoverTheCellsTheyCover) {
  // Rectangles on an integer grid: the union's area is the number of unit cells covered.
  std::mt19937 random(20261129);
  std::uniform_int_distribution<int> corner(0, 19);
  std::uniform_int_distribution<int> side(1, 6);
  for (int trial = 0; trial < 10; ++trial) {
    std::vector<PolygonWithHoles> boxes;
    std::vector<bool> covered(30 * 30, false);
    for (int k = 0; k < 60; ++k) {
      const int x = corner(random), y = corner(random), w = side(random), h = side(random);
      boxes.push_back(box(x, y, x + w, y + h));
      for (int i = x; i < x + w; ++i) {
        for (int j = y; j < y + h; ++j) covered[i * 30 + j] = true;
      }
    }
    double cells = 0.0;
    for (bool c : covered) cells += c ? 1.0 : 0.0;
    const std::vector<PolygonWithHoles> united = unionOfAreas(boxes);
    EXPECT_NEAR(area(united), cells, 1e-9);
    for (const PolygonWithHoles& part : united) {
      for (const Point2& p : part.hull) EXPECT_EQ(p, Point2(std::round(p.x()), std::round(p.y())));
    }
  }
}

TEST(UnionOfAreasTest, RefusesNonFiniteCoordinates) {
  EXPECT_THROW(unionOfAreas({box(0, 0, 1, NAN)}), InvalidInputError);
}

}  // namespace
}  // namespace kinematic_coverage::core
