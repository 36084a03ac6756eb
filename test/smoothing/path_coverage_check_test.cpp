#include "trajectory_generation_tools/smoothing/path_coverage_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "trajectory_generation_tools/smoothing/inner_smoothing.h"
#include "trajectory_generation_tools/smoothing/smoothed_path_assembler.h"

namespace kinematic_coverage::core {
namespace {

const FrustumSensor kSensor(4.0, 3.0, 0.0);
/// Cells that the sharp and smoothed paths' different sampling may leave unseen.
constexpr std::size_t kRoundingCells = 2;

/// The primitives of `waypoints` with the inner smoothing of radius r at interior corner
/// `corner` (a waypoint index) and every other corner sharp.
std::vector<PathPrimitive> withInnerArc(const std::vector<Point2>& waypoints, std::size_t corner,
                                        double r, ReplacedStretch* stretch) {
  const Point2& a = waypoints[corner - 1];
  const Point2& b = waypoints[corner];
  const Point2& c = waypoints[corner + 1];
  const std::optional<CornerSmoothing> arc =
      InnerSmoothing::compute({a, b, c, r, (b - a).normalized()});
  EXPECT_TRUE(arc.has_value());
  std::vector<std::optional<CornerSmoothing>> smoothings(waypoints.size() - 2);
  smoothings[corner - 1] = arc;
  *stretch = {b - arc->entry_distance * (b - a).normalized(), b,
              b + arc->exit_distance * (c - b).normalized()};
  return SmoothedPathAssembler::assemble(waypoints, smoothings).primitives;
}

TEST(PathCoverageCheck, TheSharpPathLosesNothingOfItself) {
  const std::vector<Point2> path{{0, 0}, {30, 0}, {30, 3}, {0, 3}, {0, 6}};
  PathCoverageCheck check({}, 0.0, {}, kSensor, path);
  const std::vector<std::optional<CornerSmoothing>> sharp(path.size() - 2);
  const std::vector<ReplacedStretch> everywhere{path};
  EXPECT_EQ(check.lostCells(SmoothedPathAssembler::assemble(path, sharp).primitives, everywhere),
            std::vector<std::size_t>{0});
}

TEST(PathCoverageCheck, AReversalAtADeadEndLosesItsTipUnlessAnotherLegSeesIt) {
  // Up a lane and back down a lane 3 m beside it: inner smoothing of the near-reversal
  // starts its arc 32 m before the far end, and the end of the bay goes unseen.
  const std::vector<Point2> dead_end{{0, 0}, {0, 40}, {3, 0}};
  ReplacedStretch stretch;
  const std::vector<PathPrimitive> cut = withInnerArc(dead_end, 1, 1.0, &stretch);
  PathCoverageCheck check({}, 0.0, {}, kSensor, dead_end);
  EXPECT_GT(check.lostCells(cut, {stretch}).front() * check.cellArea(), 10.0);  // m^2

  // The same cut, where the path later sweeps both lanes and the end again: nothing is
  // lost.
  std::vector<Point2> revisited = dead_end;
  for (const Point2& p : {Point2(-0.5, 0), Point2(-0.5, 41), Point2(3.5, 41), Point2(3.5, 0)}) {
    revisited.push_back(p);
  }
  const std::vector<PathPrimitive> cut_revisited = withInnerArc(revisited, 1, 1.0, &stretch);
  PathCoverageCheck revisited_check({}, 0.0, {}, kSensor, revisited);
  EXPECT_LE(revisited_check.lostCells(cut_revisited, {stretch}).front(), kRoundingCells);
}

TEST(PathCoverageCheck, ARightAngleAtTheWallsLosesNothingReachable) {
  // A right-angle turn at a corner of the area, 1 m from both walls, cut by a 1 m arc:
  // what the in-place rotation's footprint corners sweep beyond the arc's footprints lies
  // farther than half a footprint length from the offset free area, which is not reachable.
  PolygonWithHoles area;
  area.hull = {{-1, -1}, {21, -1}, {21, 21}, {-1, 21}};
  const std::vector<Point2> corner{{0, 0}, {20, 0}, {20, 20}};
  ReplacedStretch stretch;
  const std::vector<PathPrimitive> cut = withInnerArc(corner, 1, 1.0, &stretch);
  EXPECT_LE(PathCoverageCheck(area, 1.0, {}, kSensor, corner).lostCells(cut, {stretch}).front(),
            kRoundingCells);
  // In the open, with nothing to stop a footprint, the same cut loses area.
  EXPECT_GT(PathCoverageCheck({}, 0.0, {}, kSensor, corner).lostCells(cut, {stretch}).front(),
            kRoundingCells);
}

TEST(PathCoverageCheck, GuardingTheFreeAreaKeepsTheWallBandBeyondTheReachableArea) {
  // A footprint 4 m wide and 0.5 m long, 1 m from the walls: the reachable area reaches
  // only 0.25 m beyond the offset free area, while the sharp path's legs along the walls and
  // its turn in place see the wall band beyond it. An acute corner cut by a 1 m inner arc
  // loses its tip: of the reachable area, and more of the free area, whose check
  // (coverage_safe_area: free) counts the band too. The sharp path loses nothing of either.
  const FrustumSensor narrow(4.0, 0.5, 0.0);
  PolygonWithHoles area;
  area.hull = {{-1, -1}, {21, -1}, {21, 21}, {-1, 21}};
  const std::vector<Point2> corner{{0, 0}, {20, 0}, {12, 6}};
  ReplacedStretch stretch;
  const std::vector<PathPrimitive> cut = withInnerArc(corner, 1, 1.0, &stretch);
  PathCoverageCheck reachable(area, 1.0, {}, narrow, corner);
  PathCoverageCheck free(area, 1.0, {}, narrow, corner, CoverageSafeArea::kFree);
  const double reachable_lost = reachable.lostCells(cut, {stretch}).front() * reachable.cellArea();
  const double free_lost = free.lostCells(cut, {stretch}).front() * free.cellArea();
  EXPECT_GT(reachable_lost, 0.5);              // m^2
  EXPECT_GT(free_lost, reachable_lost + 1.0);  // m^2
  const std::vector<std::optional<CornerSmoothing>> sharp(1);
  EXPECT_EQ(
      free.lostCells(SmoothedPathAssembler::assemble(corner, sharp).primitives, {stretch}).front(),
      0u);
}

TEST(PathCoverageCheck, LaterCallsCountAsAFreshCheckDoes) {
  // A lawnmower of five lanes; the rounds of coverage-safe smoothing ask about one choice
  // of corner arcs after another. Each answer, from the remembered stretches and the
  // re-measured ones, is a fresh check's.
  PolygonWithHoles area;
  area.hull = {{-2, -2}, {32, -2}, {32, 16}, {-2, 16}};
  const std::vector<Point2> path{{0, 0},  {30, 0}, {30, 3}, {0, 3},  {0, 6},
                                 {30, 6}, {30, 9}, {0, 9},  {0, 12}, {30, 12}};
  const std::vector<std::vector<std::size_t>> rounds{{1, 3, 5, 7}, {1, 3, 5}, {3, 5}, {3, 5, 8}};
  PathCoverageCheck check(area, 1.0, {}, kSensor, path);
  for (const std::vector<std::size_t>& corners : rounds) {
    std::vector<std::optional<CornerSmoothing>> smoothings(path.size() - 2);
    std::vector<ReplacedStretch> stretches;
    for (const std::size_t corner : corners) {
      const Point2& a = path[corner - 1];
      const Point2& b = path[corner];
      const Point2& c = path[corner + 1];
      smoothings[corner - 1] = InnerSmoothing::compute({a, b, c, 1.2, (b - a).normalized()});
      ASSERT_TRUE(smoothings[corner - 1].has_value());
      stretches.push_back({b - smoothings[corner - 1]->entry_distance * (b - a).normalized(), b,
                           b + smoothings[corner - 1]->exit_distance * (c - b).normalized()});
    }
    const std::vector<PathPrimitive> primitives =
        SmoothedPathAssembler::assemble(path, smoothings).primitives;
    const std::vector<std::size_t> remembered = check.lostCells(primitives, stretches);
    EXPECT_EQ(remembered,
              PathCoverageCheck(area, 1.0, {}, kSensor, path).lostCells(primitives, stretches));
    std::size_t total = 0;
    for (const std::size_t cells : remembered) total += cells;
    EXPECT_GT(total, 0u);  // the arcs at the walls cut area the sharp turns see
  }
}

/// The sharp path `waypoints` from corner - 1 to corner + 1 with the inner smoothing of
/// radius r at interior corner `corner`: what lostCellsReplacing takes for it.
std::vector<PathPrimitive> innerArcReplacement(const std::vector<Point2>& waypoints,
                                               std::size_t corner, double r) {
  const std::vector<Point2> legs{waypoints[corner - 1], waypoints[corner], waypoints[corner + 1]};
  ReplacedStretch unused;
  return withInnerArc(legs, 1, r, &unused);
}

TEST(PathCoverageCheck, OneCornerReplacedLosesWhatTheWholePathCheckFinds) {
  // Lawnmowers in a room with random lane lengths and spacing (fixed seed): smoothing one
  // corner at a time, the windowed check of that corner alone counts what the whole-path
  // check counts for the same path.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> spacing(1.5, 4.5);
  std::uniform_real_distribution<double> jitter(-3.0, 3.0);
  for (int trial = 0; trial < 4; ++trial) {
    std::vector<Point2> path;
    double y = 0.0;
    for (int lane = 0; lane < 5; ++lane) {
      const double near_end = 2.0 + (lane % 2 == 0 ? 0.0 : jitter(random) + 3.0);
      const double far_end = 28.0 + (lane % 2 == 0 ? jitter(random) : 0.0);
      if (lane % 2 == 0) {
        path.insert(path.end(), {{near_end, y}, {far_end, y}});
      } else {
        path.insert(path.end(), {{far_end, y}, {near_end, y}});
      }
      y += spacing(random);
    }
    PolygonWithHoles area;
    area.hull = {{-1, -2}, {33, -2}, {33, y + 1}, {-1, y + 1}};
    PathCoverageCheck check(area, 1.0, {}, kSensor, path);
    std::size_t lost_somewhere = 0;
    for (std::size_t corner = 1; corner + 1 < path.size(); ++corner) {
      ReplacedStretch stretch;
      const std::vector<PathPrimitive> whole = withInnerArc(path, corner, 1.0, &stretch);
      const std::size_t expected =
          PathCoverageCheck(area, 1.0, {}, kSensor, path).lostCells(whole, {stretch}).front();
      const std::size_t windowed = check.lostCellsReplacing(
          corner - 1, corner, innerArcReplacement(path, corner, 1.0), stretch);
      EXPECT_NEAR(static_cast<double>(windowed), static_cast<double>(expected), kRoundingCells)
          << "trial " << trial << ", corner " << corner;
      lost_somewhere += expected;
    }
    EXPECT_GT(lost_somewhere, 10 * kRoundingCells);  // arcs at the walls cut reachable area
  }
}

TEST(PathCoverageCheck, OneCornerReplacedAtADeadEndLosesItsTipUnlessAnotherLegSeesIt) {
  const std::vector<Point2> dead_end{{0, 0}, {0, 40}, {3, 0}};
  ReplacedStretch stretch;
  withInnerArc(dead_end, 1, 1.0, &stretch);
  const PathCoverageCheck check({}, 0.0, {}, kSensor, dead_end);
  EXPECT_GT(check.lostCellsReplacing(0, 1, innerArcReplacement(dead_end, 1, 1.0), stretch) *
                check.cellArea(),
            10.0);  // m^2

  // Later legs that sweep both lanes and the end again see what the arc cuts; the legs
  // replaced are the same (the first two), the rest of the path stays sharp.
  std::vector<Point2> revisited = dead_end;
  for (const Point2& p : {Point2(-0.5, 0), Point2(-0.5, 41), Point2(3.5, 41), Point2(3.5, 0)}) {
    revisited.push_back(p);
  }
  const PathCoverageCheck revisited_check({}, 0.0, {}, kSensor, revisited);
  EXPECT_LE(
      revisited_check.lostCellsReplacing(0, 1, innerArcReplacement(revisited, 1, 1.0), stretch),
      kRoundingCells);
  // The sharp corner itself, as its own replacement, loses nothing.
  const std::vector<std::optional<CornerSmoothing>> sharp(1);
  EXPECT_EQ(check.lostCellsReplacing(
                0, 1, SmoothedPathAssembler::assemble(dead_end, sharp).primitives, dead_end),
            0u);
}

TEST(PathCoverageCheck, ToleratesAShareOfWhatTheSharpPathSees) {
  // One 40 m lane and back 3 m beside it under a 4 m x 3 m footprint, in the open: the
  // sharp path sees about 7 m x 43 m; 0.02 % of its cells may be lost in all.
  const std::vector<Point2> dead_end{{0, 0}, {0, 40}, {3, 0}};
  PathCoverageCheck check({}, 0.0, {}, kSensor, dead_end);
  const double seen_m2 = 7.0 * 43.0;
  EXPECT_NEAR(check.toleratedLostCells() * check.cellArea(),
              PathCoverageCheck::kToleratedLostShare * seen_m2, 0.05 * 0.0002 * seen_m2 + 0.01);
}

TEST(PathCoverageCheck, RejectsAnInvalidWallDistance) {
  EXPECT_THROW(PathCoverageCheck({}, -1.0, {}, kSensor, {{0, 0}, {1, 0}}), InvalidInputError);
  EXPECT_THROW(PathCoverageCheck({}, std::nan(""), {}, kSensor, {{0, 0}, {1, 0}}),
               InvalidInputError);
}

}  // namespace
}  // namespace kinematic_coverage::core
