#include "trajectory_generation_tools/replanning/raster_contours.h"

#include <gtest/gtest.h>

#include <random>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/validation/polygon_validator.h"

namespace kinematic_coverage::core {
namespace {

double totalArea(const std::vector<PolygonWithHoles>& polygons) {
  double sum = 0.0;
  for (const PolygonWithHoles& polygon : polygons) sum += area(polygon);
  return sum;
}

TEST(RasterContours, SquareWithAHoleAndADiagonalNeighbour) {
  const CoverageRaster raster({0, 0}, 1.0, 8, 8);
  CellMask mask(raster.cellCount(), 0);
  for (int row = 1; row <= 4; ++row) {
    for (int column = 1; column <= 4; ++column) {
      if (!(row == 2 && column == 2)) mask[raster.index(row, column)] = 1;
    }
  }
  mask[raster.index(5, 5)] = 1;  // touches the square only at the corner (5, 5)
  const auto polygons = traceMaskContours(raster, mask);
  ASSERT_EQ(polygons.size(), 2u);
  EXPECT_NEAR(totalArea(polygons), 16.0, 1e-12);
  for (const PolygonWithHoles& polygon : polygons) {
    EXPECT_GT(signedArea(polygon.hull), 0.0);
    for (const Ring& hole : polygon.holes) EXPECT_LT(signedArea(hole), 0.0);
  }
  const auto& square =
      polygons[0].hull.size() == 4 && area(polygons[0]) == 15.0 ? polygons[0] : polygons[1];
  EXPECT_EQ(square.hull.size(), 4u);  // collinear vertices dropped
  EXPECT_EQ(square.holes.size(), 1u);
}

/// Random masks without pinches: the polygons' total area equals the mask's, and every
/// polygon is valid.
TEST(RasterContours, RandomMasksGiveValidPolygonsOfTheMasksArea) {
  std::mt19937 rng(808);
  std::bernoulli_distribution bit(0.55);
  for (int trial = 0; trial < 200; ++trial) {
    const CoverageRaster raster({-3.0, 2.0}, 0.5, 12, 9);
    CellMask mask(raster.cellCount(), 0);
    for (auto& cell : mask) cell = bit(rng) ? 1 : 0;
    removeDiagonalPinches(raster, mask);
    const auto polygons = traceMaskContours(raster, mask);
    EXPECT_NEAR(totalArea(polygons), raster.area(mask), 1e-9) << "trial " << trial;
    for (const PolygonWithHoles& polygon : polygons) {
      EXPECT_NO_THROW(PolygonValidator().validate(polygon)) << "trial " << trial;
    }
  }
}

TEST(RasterContours, PinchesAreClearedUntilNoneIsLeft) {
  const CoverageRaster raster({0, 0}, 1.0, 3, 3);
  // A checkerboard: every 2 x 2 block is a pinch.
  CellMask mask = {1, 0, 1, 0, 1, 0, 1, 0, 1};
  EXPECT_GT(removeDiagonalPinches(raster, mask), 0u);
  for (int row = 0; row + 1 < 3; ++row) {
    for (int column = 0; column + 1 < 3; ++column) {
      const bool a = mask[raster.index(row, column)], b = mask[raster.index(row, column + 1)];
      const bool c = mask[raster.index(row + 1, column)],
                 d = mask[raster.index(row + 1, column + 1)];
      EXPECT_FALSE((a && d && !b && !c) || (b && c && !a && !d));
    }
  }
  CellMask solid(9, 1);
  EXPECT_EQ(removeDiagonalPinches(raster, solid), 0u);
}

TEST(RasterContours, EmptyMaskAndWrongSize) {
  const CoverageRaster raster({0, 0}, 1.0, 3, 3);
  EXPECT_TRUE(traceMaskContours(raster, CellMask(9, 0)).empty());
  EXPECT_THROW(traceMaskContours(raster, CellMask(8, 0)), InvalidInputError);
}

}  // namespace
}  // namespace kinematic_coverage::core
