#include "polygon_coverage_ros_bridge/sweeps/coverage_raster.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "test/support/random_polygons.h"
#include "test/support/test_shapes.h"

namespace kinematic_coverage::core {
namespace {

using testing::turnedSquare;

double perimeter(const PolygonWithHoles& polygon) {
  double length = 0.0;
  const auto add = [&](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      length += (ring[(i + 1) % ring.size()] - ring[i]).norm();
    }
  };
  add(polygon.hull);
  for (const Ring& hole : polygon.holes) add(hole);
  return length;
}

TEST(CoverageRaster, AlignedRectangleIsExact) {
  const CoverageRaster raster({0.0, 0.0}, 0.5, 40, 30);
  const PolygonWithHoles rectangle{{{1.0, 2.0}, {11.0, 2.0}, {11.0, 7.0}, {1.0, 7.0}}, {}};
  const CellMask mask = raster.rasterize(rectangle);
  EXPECT_DOUBLE_EQ(raster.area(mask), 50.0);
  // Centres on the left and bottom edges are in, on the right and top edges out.
  const CoverageRaster shifted({0.25, 0.25}, 0.5, 40, 30);
  EXPECT_DOUBLE_EQ(shifted.area(shifted.rasterize(rectangle)), 50.0);
  EXPECT_EQ(mask[raster.index(4, 2)], 1);
  EXPECT_EQ(mask[raster.index(3, 2)], 0);
  EXPECT_EQ(mask[raster.index(4, 21)], 1);
  EXPECT_EQ(mask[raster.index(4, 22)], 0);
}

TEST(CoverageRaster, SquareWithHoleExcludesTheHole) {
  PolygonWithHoles square{turnedSquare({10.0, 10.0}, 20.0, 0.3), {}};
  Ring hole = turnedSquare({12.0, 9.0}, 5.0, -0.7);
  std::reverse(hole.begin(), hole.end());
  square.holes.push_back(hole);
  const CoverageRaster raster = CoverageRaster::covering(square, {0.02, 1e-3, 4'000'000});
  const CellMask mask = raster.rasterize(square);
  EXPECT_NEAR(raster.area(mask), 375.0, 375.0 * 1e-3);
  for (std::size_t i = 0; i < mask.size(); ++i) {
    const Point2 centre = raster.cellCentre(i);
    if (insideRing(centre, hole)) EXPECT_EQ(mask[i], 0) << centre.transpose();
    if (mask[i] != 0) EXPECT_TRUE(insideRing(centre, square.hull)) << centre.transpose();
  }
}

TEST(CoverageRaster, TilesShareNoCell) {
  // Two turned rectangles sharing an edge: no cell counted twice, none lost.
  const Point2 a(1.3, 0.7);
  const Point2 b(9.1, 3.2);
  const Point2 normal = Point2(-(b - a).y(), (b - a).x()).normalized() * 4.0;
  const Ring left{a, b, b + normal, a + normal};
  const Ring right{a - normal, b - normal, b, a};
  const Ring both{a - normal, b - normal, b + normal, a + normal};
  const CoverageRaster raster({-5.0, -5.0}, 0.037, 600, 500);
  const CellMask left_mask = raster.rasterize({left, {}});
  const CellMask right_mask = raster.rasterize({right, {}});
  const CellMask both_mask = raster.rasterize({both, {}});
  std::size_t overlap = 0;
  std::size_t mismatch = 0;
  for (std::size_t i = 0; i < both_mask.size(); ++i) {
    overlap += (left_mask[i] != 0 && right_mask[i] != 0) ? 1 : 0;
    mismatch += ((left_mask[i] != 0 || right_mask[i] != 0) != (both_mask[i] != 0)) ? 1 : 0;
  }
  EXPECT_EQ(overlap, 0u);
  EXPECT_EQ(mismatch, 0u);
}

TEST(CoverageRaster, ConvexSpansMatchPolygonRasterization) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coordinate(-3.0, 23.0);
  const CoverageRaster raster({0.0, 0.0}, 0.1, 200, 200);
  for (int trial = 0; trial < 50; ++trial) {
    const Ring square = turnedSquare({coordinate(rng), coordinate(rng)}, 7.0, coordinate(rng));
    CellMask from_spans(raster.cellCount(), 0);
    std::vector<CellSpan> spans;
    raster.appendConvexSpans(square, spans);
    for (const CellSpan& span : spans) {
      for (int column = span.begin; column < span.end; ++column) {
        from_spans[raster.index(span.row, column)] = 1;
      }
    }
    EXPECT_EQ(from_spans, raster.rasterize({square, {}})) << "trial " << trial;
  }
}

TEST(CoverageRaster, DegenerateConvexPolygonHasNoCells) {
  const CoverageRaster raster({0.0, 0.0}, 0.1, 100, 100);
  std::vector<CellSpan> spans;
  raster.appendConvexSpans({{1.0, 1.0}, {5.0, 5.0}, {5.0, 5.0}, {1.0, 1.0}}, spans);
  raster.appendConvexSpans({{1.0, 1.0}, {5.0, 5.0}}, spans);
  raster.appendConvexSpans(
      {{1.0, 1.0}, {std::numeric_limits<double>::quiet_NaN(), 5.0}, {5.0, 1.0}}, spans);
  EXPECT_TRUE(spans.empty());
}

TEST(CoverageRaster, RandomMapsConvergeToPolygonArea) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> size(50.0, 200.0);
  for (int trial = 0; trial < 30; ++trial) {
    const PolygonWithHoles map = testing::randomMap(rng, size(rng), 15, 2.0);
    const double exact = area(map);
    const double boundary = perimeter(map);
    // The automatic resolution meets the 0.1 % target.
    const CoverageRaster automatic = CoverageRaster::covering(map);
    const double automatic_error = std::abs(automatic.area(automatic.rasterize(map)) - exact);
    EXPECT_LE(automatic_error, 1e-3 * exact) << "trial " << trial;
    // A quarter of the cell budget still does in practice: boundary errors cancel.
    const CoverageRaster coarse = CoverageRaster::covering(map, {0.0, 1e-3, 1'000'000});
    EXPECT_LE(std::abs(coarse.area(coarse.rasterize(map)) - exact), 1e-3 * exact)
        << "trial " << trial;
    // Every cell size respects the bound perimeter * cell / 2, so the error vanishes.
    for (const double cell : {2.0, 0.5, 0.125}) {
      const CoverageRaster raster = CoverageRaster::covering(map, {cell, 1e-3, 4'000'000});
      const double error = std::abs(raster.area(raster.rasterize(map)) - exact);
      EXPECT_LE(error, 0.5 * boundary * cell) << "trial " << trial << " cell " << cell;
    }
  }
}

TEST(CoverageRaster, AutomaticResolutionFollowsAccuracyAndBudget) {
  const PolygonWithHoles square{turnedSquare({0.0, 0.0}, 20.0, 0.0), {}};
  // 2 * 1e-3 * 400 / 80 = 0.01 m.
  const CoverageRaster fine = CoverageRaster::covering(square, {0.0, 1e-3, 10'000'000});
  EXPECT_NEAR(fine.cellSize(), 0.01, 1e-12);
  const CoverageRaster budget = CoverageRaster::covering(square, {0.0, 1e-3, 10'000});
  EXPECT_LE(budget.cellCount(), 10'000u);
  EXPECT_GT(budget.cellCount(), 9'000u);
  const CoverageRaster given = CoverageRaster::covering(square, {0.25, 1e-3, 10'000});
  EXPECT_DOUBLE_EQ(given.cellSize(), 0.25);
  EXPECT_LE(given.origin().x(), -10.0);
  EXPECT_GE(given.origin().x() + given.columns() * given.cellSize(), 10.0);
}

TEST(CoverageRaster, AutomaticCellSizeStaysAboveItsFloor) {
  // The accuracy asks for 0.01 m; a 0.05 m floor wins, a 0.002 m floor does not.
  const PolygonWithHoles square{turnedSquare({0.0, 0.0}, 20.0, 0.0), {}};
  EXPECT_DOUBLE_EQ(CoverageRaster::covering(square, {0.0, 1e-3, 10'000'000, 0.05}).cellSize(),
                   0.05);
  EXPECT_NEAR(CoverageRaster::covering(square, {0.0, 1e-3, 10'000'000, 0.002}).cellSize(), 0.01,
              1e-12);
  // The budget still coarsens beyond the floor; an explicit cell size ignores it.
  EXPECT_LE(CoverageRaster::covering(square, {0.0, 1e-3, 10'000, 0.05}).cellCount(), 10'000u);
  EXPECT_DOUBLE_EQ(CoverageRaster::covering(square, {0.02, 1e-3, 10'000'000, 0.05}).cellSize(),
                   0.02);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(CoverageRaster::covering(square, {0.0, 1e-3, 1'000'000, -0.05}), InvalidInputError);
  EXPECT_THROW(CoverageRaster::covering(square, {0.0, 1e-3, 1'000'000, nan}), InvalidInputError);
}

TEST(CoverageRaster, RejectsInvalidInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const PolygonWithHoles square{turnedSquare({0.0, 0.0}, 20.0, 0.0), {}};
  EXPECT_THROW(CoverageRaster({0.0, 0.0}, 0.0, 10, 10), InvalidInputError);
  EXPECT_THROW(CoverageRaster({0.0, 0.0}, -1.0, 10, 10), InvalidInputError);
  EXPECT_THROW(CoverageRaster({nan, 0.0}, 1.0, 10, 10), InvalidInputError);
  EXPECT_THROW(CoverageRaster({0.0, 0.0}, 1.0, 0, 10), InvalidInputError);
  EXPECT_THROW(CoverageRaster::covering(square, {1e-4, 1e-3, 1'000'000}), InvalidInputError);
  EXPECT_THROW(CoverageRaster::covering(square, {-0.1, 1e-3, 1'000'000}), InvalidInputError);
  EXPECT_THROW(CoverageRaster::covering(square, {0.0, 0.0, 1'000'000}), InvalidInputError);
  EXPECT_THROW(CoverageRaster::covering(square, {0.0, 1e-3, 0}), InvalidInputError);
  EXPECT_THROW(CoverageRaster::covering(square, {0.0, 1e-3, 8}), InvalidInputError);
  EXPECT_EQ(CoverageRaster::covering(square, {0.0, 1e-3, 9}).cellCount(), 9u);
  EXPECT_EQ(CoverageRaster::covering(square, {0.0, 1e9, 100}).cellCount(), 9u);
  EXPECT_THROW(CoverageRaster::covering({{{0, 0}, {1, 1}, {2, 2}}, {}}), InvalidInputError);
  EXPECT_THROW(CoverageRaster::covering({{{0, 0}, {1, 0}}, {}}), InvalidInputError);
  PolygonWithHoles broken = square;
  broken.hull[1].x() = nan;
  EXPECT_THROW(CoverageRaster::covering(broken), InvalidInputError);
  const CoverageRaster raster({0.0, 0.0}, 1.0, 10, 10);
  EXPECT_THROW(raster.rasterize(broken), InvalidInputError);
  PolygonWithHoles huge = square;
  huge.holes.push_back({{0, 0}, {0, 1e300}, {1, 0}});
  EXPECT_THROW(raster.rasterize(huge), InvalidInputError);
  // Far outside the grid or nearly horizontal: clipped, no crash.
  const PolygonWithHoles far{{{-1e9, -1e9}, {1e9, -1e9 + 1e-300}, {1e9, 1e9}}, {}};
  EXPECT_GT(CoverageRaster::countCells(raster.rasterize(far)), 0u);
}

TEST(CoverageRaster, AreaFractionsOfAnEdgeAlongTheGridAreExact) {
  // Edges a quarter cell off the cell centres: the centre samples miss (or add) a quarter
  // cell along all of them, the fractions measure them.
  const CoverageRaster raster({0, 0}, 1.0, 12, 12);
  const PolygonWithHoles square{{{1.25, 1.25}, {10.75, 1.25}, {10.75, 10.75}, {1.25, 10.75}}, {}};
  const double exact = 9.5 * 9.5;
  EXPECT_GT(std::abs(raster.area(raster.rasterize(square)) - exact), 5.0);
  const CellFractions fractions = raster.areaFractions(square);
  double sum = 0.0;
  for (float f : fractions) sum += f;
  EXPECT_NEAR(sum, exact, 1e-4);
  EXPECT_FLOAT_EQ(fractions[raster.index(1, 1)], 0.75f * 0.75f);
  EXPECT_FLOAT_EQ(fractions[raster.index(5, 1)], 0.75f);
  EXPECT_FLOAT_EQ(fractions[raster.index(5, 5)], 1.0f);
  EXPECT_FLOAT_EQ(fractions[raster.index(0, 0)], 0.0f);
}

TEST(CoverageRaster, AreaFractionsOfRandomMapsSumToTheirArea) {
  // Within perimeter * cell / (2 * kFractionLines), holes and slanted edges included.
  std::mt19937 rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    const PolygonWithHoles map = testing::randomMap(rng, 40.0, 6, 2.0);
    const CoverageRaster raster = CoverageRaster::covering(map, {0.3, 1e-3, 4'000'000});
    double perimeter = 0.0;
    auto addPerimeter = [&](const Ring& ring) {
      for (std::size_t i = 0; i < ring.size(); ++i) {
        perimeter += (ring[(i + 1) % ring.size()] - ring[i]).norm();
      }
    };
    addPerimeter(map.hull);
    for (const Ring& hole : map.holes) addPerimeter(hole);
    double sum = 0.0;
    for (float f : raster.areaFractions(map)) sum += f;
    EXPECT_NEAR(sum * raster.cellArea(), area(map),
                perimeter * raster.cellSize() / (2.0 * CoverageRaster::kFractionLines))
        << "trial " << trial;
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
