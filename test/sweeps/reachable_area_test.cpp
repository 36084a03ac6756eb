#include "polygon_coverage_ros_bridge/sweeps/reachable_area.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "test/support/test_shapes.h"

namespace kinematic_coverage::core {
namespace {

using testing::turnedSquare;

TEST(ReachableArea, DilationMatchesBruteForce) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const CoverageRaster raster({-1.0, 2.0}, 0.3, 70, 55);
  for (int trial = 0; trial < 20; ++trial) {
    CellMask mask(raster.cellCount(), 0);
    const double density = 0.002 + 0.05 * unit(rng);
    for (auto& cell : mask) cell = unit(rng) < density ? 1 : 0;
    const double radius = 4.0 * unit(rng);
    const CellMask grown = dilateMask(raster, mask, radius);
    std::vector<Point2> set_centres;
    for (std::size_t j = 0; j < mask.size(); ++j) {
      if (mask[j] != 0) set_centres.push_back(raster.cellCentre(j));
    }
    const double reach = radius + 0.5 * raster.cellSize();
    for (std::size_t i = 0; i < mask.size(); ++i) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const Point2& centre : set_centres) {
        nearest = std::min(nearest, (raster.cellCentre(i) - centre).norm());
      }
      if (nearest <= reach - 1e-9) EXPECT_EQ(grown[i], 1) << "trial " << trial << " cell " << i;
      if (nearest > reach + 1e-9) EXPECT_EQ(grown[i], 0) << "trial " << trial << " cell " << i;
    }
  }
}

TEST(ReachableArea, SeveralRadiiAtOnceAreTheMasksOfOneCallEach) {
  // One distance transform, capped for the largest radius, thresholded at each: the same
  // masks as one call per radius (whose cap follows its own radius), 0 giving the mask.
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const CoverageRaster raster({3.0, -2.0}, 0.05, 120, 400);
  for (int trial = 0; trial < 6; ++trial) {
    CellMask mask(raster.cellCount(), 0);
    const double density = 0.0005 + 0.01 * unit(rng);
    for (auto& cell : mask) cell = unit(rng) < density ? 1 : 0;
    const std::vector<double> radii = {0.3 * unit(rng), 0.0, 15.0 * unit(rng), 3.0 * unit(rng)};
    const std::vector<CellMask> grown = dilateMask(raster, mask, radii);
    ASSERT_EQ(grown.size(), radii.size());
    for (std::size_t k = 0; k < radii.size(); ++k) {
      EXPECT_EQ(grown[k], dilateMask(raster, mask, radii[k]))
          << "trial " << trial << " radius " << k;
    }
    EXPECT_EQ(grown[1], mask);
  }
  EXPECT_THROW(dilateMask(raster, CellMask(raster.cellCount(), 0), {1.0, -1.0}), InvalidInputError);
  EXPECT_TRUE(dilateMask(raster, CellMask(raster.cellCount(), 0), std::vector<double>{}).empty());
}

TEST(ReachableArea, FewSetCellsAndManyMeetTheSameExactCriterion) {
  // A mask of a few set cells is grown by discs stamped around them, a denser one by the
  // distance transform: both set exactly the cells whose centre-to-centre distance in cells
  // squared is at most reach squared, ties included (reach 3 and 4.5 cells).
  const CoverageRaster raster({0.0, 0.0}, 0.1, 200, 150);
  std::mt19937 rng(29);
  std::uniform_int_distribution<std::size_t> cell(0, raster.cellCount() - 1);
  for (const std::size_t seeds : {std::size_t{3}, std::size_t{40}, std::size_t{3000}}) {
    CellMask mask(raster.cellCount(), 0);
    std::vector<std::size_t> set;
    for (std::size_t k = 0; k < seeds; ++k) {
      const std::size_t i = cell(rng);
      if (mask[i] == 0) set.push_back(i);
      mask[i] = 1;
    }
    for (const double radius : {0.25, 0.4}) {
      const CellMask grown = dilateMask(raster, mask, radius);
      const double reach = radius / raster.cellSize() + 0.5;
      for (std::size_t i = 0; i < mask.size(); ++i) {
        const long long row = static_cast<long long>(i) / raster.columns();
        const long long column = static_cast<long long>(i) % raster.columns();
        bool within = false;
        for (const std::size_t j : set) {
          const long long dy = row - static_cast<long long>(j) / raster.columns();
          const long long dx = column - static_cast<long long>(j) % raster.columns();
          within = within || static_cast<double>(dx * dx + dy * dy) <= reach * reach;
        }
        ASSERT_EQ(grown[i], within ? 1 : 0)
            << seeds << " seeds, radius " << radius << " cell " << i;
      }
    }
  }
}

TEST(ReachableArea, LargeGridsOnSeveralThreadsMeetTheExactCriterion) {
  // A grid large enough for the transform to run in blocks on every thread: the same cells
  // as a disc stamped around each set cell.
  const CoverageRaster raster({0.0, 0.0}, 0.1, 640, 500);
  std::mt19937 rng(31);
  std::uniform_int_distribution<std::size_t> cell(0, raster.cellCount() - 1);
  CellMask mask(raster.cellCount(), 0);
  for (int k = 0; k < 6000; ++k) mask[cell(rng)] = 1;
  const double radius = 0.45;
  const double reach = radius / raster.cellSize() + 0.5;
  CellMask expected = mask;
  for (std::size_t j = 0; j < mask.size(); ++j) {
    if (mask[j] == 0) continue;
    const int row = static_cast<int>(j) / raster.columns();
    const int column = static_cast<int>(j) % raster.columns();
    for (int dy = -5; dy <= 5; ++dy) {
      for (int dx = -5; dx <= 5; ++dx) {
        const int r = row + dy;
        const int c = column + dx;
        if (r < 0 || r >= raster.rows() || c < 0 || c >= raster.columns()) continue;
        if (static_cast<double>(dx * dx + dy * dy) <= reach * reach)
          expected[raster.index(r, c)] = 1;
      }
    }
  }
  EXPECT_EQ(dilateMask(raster, mask, radius), expected);
}

TEST(ReachableArea, LongReachMatchesBruteForce) {
  // A reach of hundreds of cells (wider distance storage).
  const CoverageRaster raster({0.0, 0.0}, 0.01, 300, 290);
  CellMask mask(raster.cellCount(), 0);
  const std::vector<std::size_t> seeds{raster.index(10, 20), raster.index(280, 150),
                                       raster.index(140, 299)};
  for (const std::size_t i : seeds) mask[i] = 1;
  const double radius = 2.7;
  const CellMask grown = dilateMask(raster, mask, radius);
  const double reach = radius + 0.5 * raster.cellSize();
  for (std::size_t i = 0; i < mask.size(); ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const std::size_t j : seeds) {
      nearest = std::min(nearest, (raster.cellCentre(i) - raster.cellCentre(j)).norm());
    }
    if (std::abs(nearest - reach) > 1e-9) {
      ASSERT_EQ(grown[i], nearest < reach ? 1 : 0) << "cell " << i;
    }
  }
}

TEST(ReachableArea, SquareOffsetByOneMetreWithFrustumFootprint) {
  // Free square of 20 m, offset free area 18 m, footprint length 1.6 m: the offset square
  // grown by 0.8 m, a rounded square, still inside the free square.
  for (const double angle : {0.0, 0.37}) {
    const PolygonWithHoles free_area{turnedSquare({3.0, -2.0}, 20.0, angle), {}};
    const PolygonWithHoles offset_area{turnedSquare({3.0, -2.0}, 18.0, angle), {}};
    const CoverageRaster raster = CoverageRaster::covering(free_area, {0.01, 1e-3, 10'000'000});
    const CellMask reachable =
        reachableArea(raster, raster.rasterize(free_area), raster.rasterize(offset_area), 1.6);
    const double expected = 18.0 * 18.0 + 4.0 * 18.0 * 0.8 + M_PI * 0.8 * 0.8;
    EXPECT_NEAR(raster.area(reachable), expected, 1e-3 * expected) << "angle " << angle;
  }
}

// Measured against the polygons, every cell's decision is the exact one at its centre:
// reachable when the centre lies in the free area and within L/2 of the offset area (a
// turned square with a square hole), on coarse and fine cells and at two angles.
TEST(ReachableArea, FromPolygonsEveryCellIsDecidedAtItsCentre) {
  const double half_length = 0.8;
  for (const double angle : {0.0, 0.37}) {
    for (const double cell : {0.05, 0.13}) {
      const PolygonWithHoles free_area{turnedSquare({3.0, -2.0}, 20.0, angle),
                                       {turnedSquare({3.0, -2.0}, 4.0, angle)}};
      PolygonWithHoles offset_area{turnedSquare({3.0, -2.0}, 18.0, angle),
                                   {turnedSquare({3.0, -2.0}, 6.0, angle)}};
      std::reverse(offset_area.holes[0].begin(), offset_area.holes[0].end());
      const CoverageRaster raster = CoverageRaster::covering(free_area, {cell, 1e-3, 4'000'000});
      const CellMask free_mask = raster.rasterize(free_area);
      const CellMask offset_mask = raster.rasterize(offset_area);
      const CellMask exact =
          reachableArea(raster, free_mask, offset_mask, {offset_area}, 2.0 * half_length);
      std::size_t differing_from_grown = 0;
      const CellMask grown = reachableArea(raster, free_mask, offset_mask, 2.0 * half_length);
      for (std::size_t i = 0; i < exact.size(); ++i) {
        const Point2 centre = raster.cellCentre(i);
        const double distance =
            contains(offset_area, centre) ? 0.0 : distanceToBoundary(centre, offset_area);
        const bool expected = free_mask[i] != 0 && distance <= half_length;
        if (std::abs(distance - half_length) > 1e-9) {
          ASSERT_EQ(exact[i] != 0, expected)
              << "angle " << angle << " cell " << cell << " at " << centre.transpose();
        }
        if (exact[i] != grown[i]) ++differing_from_grown;
      }
      // The grown rim is off by up to half a cell: a ragged line of cells along the rim.
      EXPECT_GT(differing_from_grown, 0u);
    }
  }
}

TEST(ReachableArea, ReachIsCutByTheFreeArea) {
  // Offset by 0.5 m with a 3 m footprint: the grown square would leave the free square.
  const PolygonWithHoles free_area{turnedSquare({0.0, 0.0}, 10.0, 0.2), {}};
  const PolygonWithHoles offset_area{turnedSquare({0.0, 0.0}, 9.0, 0.2), {}};
  const CoverageRaster raster = CoverageRaster::covering(free_area, {0.01, 1e-3, 4'000'000});
  const CellMask free_mask = raster.rasterize(free_area);
  const CellMask reachable = reachableArea(raster, free_mask, raster.rasterize(offset_area), 3.0);
  EXPECT_EQ(reachable, free_mask);
}

TEST(ReachableArea, LineSensorReachesTheOffsetAreaOnly) {
  const PolygonWithHoles free_area{turnedSquare({0.0, 0.0}, 20.0, 0.5), {}};
  const PolygonWithHoles offset_area{turnedSquare({0.0, 0.0}, 18.0, 0.5), {}};
  const CoverageRaster raster = CoverageRaster::covering(free_area);
  const CellMask offset_mask = raster.rasterize(offset_area);
  EXPECT_EQ(reachableArea(raster, raster.rasterize(free_area), offset_mask, 0.0), offset_mask);
  EXPECT_NEAR(raster.area(offset_mask), 324.0, 0.324);
}

TEST(ReachableArea, RejectsInvalidInput) {
  const CoverageRaster raster({0.0, 0.0}, 1.0, 10, 10);
  const CellMask mask(raster.cellCount(), 1);
  EXPECT_THROW(dilateMask(raster, mask, -1.0), InvalidInputError);
  EXPECT_THROW(dilateMask(raster, mask, std::numeric_limits<double>::infinity()),
               InvalidInputError);
  EXPECT_THROW(dilateMask(raster, CellMask(5, 1), 1.0), InvalidInputError);
  EXPECT_THROW(reachableArea(raster, mask, CellMask(5, 1), 1.0), InvalidInputError);
  EXPECT_THROW(reachableArea(raster, mask, mask, std::numeric_limits<double>::quiet_NaN()),
               InvalidInputError);
  // An empty mask stays empty; a huge radius fills the grid.
  EXPECT_EQ(dilateMask(raster, CellMask(raster.cellCount(), 0), 5.0),
            CellMask(raster.cellCount(), 0));
  CellMask one(raster.cellCount(), 0);
  one[raster.index(3, 4)] = 1;
  EXPECT_EQ(dilateMask(raster, one, 1e12), mask);
}

}  // namespace
}  // namespace kinematic_coverage::core
