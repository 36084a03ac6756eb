#include "polygon_coverage_ros_bridge/decomposition/best_decomposition.h"

#include <gtest/gtest.h>

#include <cmath>

#include "polygon_coverage_ros_bridge/decomposition/sweep_direction.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

TEST(BestDecomposition, LongRectangleIsSweptAlongItsLength) {
  const PolygonWithHoles rectangle = {{{0, 0}, {50, 0}, {50, 5}, {0, 5}}, {}};
  const Decomposition best = computeBestDecomposition(rectangle, DecompositionType::kBoustrophedon);
  ASSERT_EQ(best.cells.size(), 1u);
  EXPECT_NEAR(best.total_altitude, 5.0, 1e-9);
  EXPECT_NEAR(std::abs(std::sin(best.cells[0].sweep_directions.front())), 0.0, 1e-9);
}

TEST(BestDecomposition, CellsHaveMonotoneDirectionsAndTile) {
  const PolygonWithHoles region = {
      {{0, 0}, {30, 0}, {30, 30}, {0, 30}},
      {{{8, 8}, {8, 12}, {12, 12}, {12, 8}}, {{18, 15}, {20, 22}, {24, 16}}}};
  for (auto type : {DecompositionType::kBoustrophedon, DecompositionType::kTrapezoidal}) {
    const Decomposition best = computeBestDecomposition(region, type);
    double total = 0.0;
    double altitudes = 0.0;
    for (const Cell& cell : best.cells) {
      ASSERT_FALSE(cell.sweep_directions.empty());
      for (double direction : cell.sweep_directions) {
        EXPECT_TRUE(isMonotone(cell.polygon, direction));
        EXPECT_GE(altitude(cell.polygon, direction), cell.altitude - 1e-9);
      }
      EXPECT_NEAR(altitude(cell.polygon, cell.sweep_directions.front()), cell.altitude, 1e-9);
      total += signedArea(cell.polygon);
      altitudes += cell.altitude;
    }
    EXPECT_NEAR(total, area(region), 1e-6);
    EXPECT_NEAR(altitudes, best.total_altitude, 1e-9);
  }
}

TEST(BestDecomposition, BoustrophedonNeedsNoMoreAltitudeThanTrapezoidal) {
  const PolygonWithHoles area = {{{0, 0}, {40, 0}, {45, 20}, {20, 35}, {-5, 20}},
                                 {{{10, 10}, {12, 16}, {16, 9}}}};
  const double boustrophedon =
      computeBestDecomposition(area, DecompositionType::kBoustrophedon).total_altitude;
  const double trapezoidal =
      computeBestDecomposition(area, DecompositionType::kTrapezoidal).total_altitude;
  EXPECT_LE(boustrophedon, trapezoidal + 1e-9);
}

}  // namespace
}  // namespace kinematic_coverage::core
