#include "polygon_coverage_ros_bridge/sweeps/seen_area.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/sweeps/waypoint_path_poses.h"

namespace kinematic_coverage::core {
namespace {

/// Index of the cell containing `p` (assumed inside the grid).
std::size_t cellAt(const CoverageRaster& raster, const Point2& p) {
  const Point2 local = (p - raster.origin()) / raster.cellSize();
  return raster.index(static_cast<int>(std::floor(local.y())),
                      static_cast<int>(std::floor(local.x())));
}

/// Area of the seen cells.
double seenArea(const SeenArea& seen) { return seen.raster().area(seen.seenMask()); }

/// Poses along a straight leg from `from` to `to`, `count` >= 2 of them, heading along it.
std::vector<Pose2> straightLeg(const Point2& from, const Point2& to, int count) {
  const double heading = std::atan2(to.y() - from.y(), to.x() - from.x());
  std::vector<Pose2> poses;
  for (int k = 0; k < count; ++k) {
    const Point2 p = from + (to - from) * k / (count - 1.0);
    poses.push_back({p.x(), p.y(), heading});
  }
  return poses;
}

/// Poses along a circle of `radius` about `centre`, from angle `from` to `to` (counter-
/// clockwise, heading along the tangent), `count` of them.
std::vector<Pose2> circleArc(const Point2& centre, double radius, double from, double to,
                             int count) {
  std::vector<Pose2> poses;
  for (int k = 0; k < count; ++k) {
    const double t = from + (to - from) * k / (count - 1.0);
    poses.push_back({centre.x() + radius * std::cos(t), centre.y() + radius * std::sin(t),
                     std::atan2(std::cos(t), -std::sin(t))});
  }
  return poses;
}

TEST(SeenArea, StraightSweepSeesWidthTimesLengthPlusFootprint) {
  const FrustumSensor sensor(4.0, 2.0, 0.0);
  const CoverageRaster raster({0.0, 0.0}, 0.04, 2000, 1500);
  for (const double heading : {0.0, 0.3, -2.1}) {
    const Point2 from(40.0, 30.0);
    const Point2 to = from + 25.0 * Point2(std::cos(heading), std::sin(heading));
    for (const int count : {2, 101}) {
      SeenArea seen(raster);
      seen.addTrajectory(straightLeg(from, to, count), sensor);
      EXPECT_NEAR(seenArea(seen), 4.0 * (25.0 + 2.0), 1e-3 * 108.0)
          << "heading " << heading << " poses " << count;
    }
  }
}

TEST(SeenArea, FullInPlaceRotationSeesDiskOfHalfDiagonal) {
  // A sampled trajectory sees the union of its footprints, which fills the disk as the
  // sampling gets dense.
  const FrustumSensor sensor(4.0, 2.0, 0.0);
  const CoverageRaster raster({25.0, 25.0}, 0.02, 500, 500);
  const double disk = M_PI * (4.0 * 4.0 + 2.0 * 2.0) / 4.0;
  std::vector<Pose2> poses;
  const int count = 4000;
  for (int k = 0; k <= count; ++k) poses.push_back({30.0, 30.0, 2.0 * M_PI * k / count});
  SeenArea seen(raster);
  seen.addTrajectory(poses, sensor);
  EXPECT_NEAR(seenArea(seen), disk, 1e-3 * disk);
  // The middle is seen all along: one visit.
  EXPECT_EQ(seen.visits(cellAt(raster, {30.003, 30.002})), 1u);
}

TEST(SeenArea, WaypointPathUTurnSweepsTheWholeDisk) {
  // Out and back: a half turn in place of a rectangle passes over its whole circumscribed
  // disk, even with a coarse rotation step.
  const FrustumSensor sensor(4.0, 2.0, 0.0);
  const CoverageRaster raster({5.0, 20.0}, 0.01, 4000, 1000);
  const Point2 turn_point(40.0, 25.0);
  const double radius = std::sqrt(5.0);
  const double spacing = 0.002;
  std::size_t inside = 0;
  for (double x = 36.0 + 0.5 * spacing; x < 44.0; x += spacing) {
    for (double y = 21.0 + 0.5 * spacing; y < 29.0; y += spacing) {
      const bool in_lane = x <= 41.0 && std::abs(y - 25.0) <= 2.0;
      if (!in_lane && (Point2(x, y) - turn_point).norm() <= radius) ++inside;
    }
  }
  // Lane [9, 41] x [23, 27] plus the disk beyond it.
  const double expected = 32.0 * 4.0 + inside * spacing * spacing;
  for (const double step : {0.2, 1.0, M_PI}) {
    SeenArea seen(raster);
    seen.addWaypointPath({{10, 25, 0}, {40, 25, 0}, {10, 25, 0}}, sensor, step);
    EXPECT_NEAR(seenArea(seen), expected, 1e-3 * expected) << "rotation step " << step;
  }
}

TEST(SeenArea, WaypointPathQuarterTurnMatchesContinuousRotation) {
  const FrustumSensor sensor(4.0, 2.0, 0.0);
  const Point2 centre(5.0, 5.0);
  const CoverageRaster raster({0.0, 0.0}, 0.01, 1000, 1000);
  SeenArea seen(raster);
  // Legs of zero width in effect: a tiny step before and after the turn.
  seen.addWaypointPath({{centre.x() - 1e-6, centre.y(), 0.0},
                        {centre.x(), centre.y(), 0.0},
                        {centre.x(), centre.y() + 1e-6, 0.0}},
                       sensor, 0.2);
  // Independent: a point is seen when the rectangle turned by some angle in [0, pi/2],
  // finely sampled, holds it.
  std::vector<Point2> axes;
  const int angles = 2000;
  for (int k = 0; k <= angles; ++k) {
    const double yaw = 0.5 * M_PI * k / angles;
    axes.emplace_back(std::cos(yaw), std::sin(yaw));
  }
  const double spacing = 0.005;
  std::size_t inside = 0;
  for (double x = 2.0 + 0.5 * spacing; x < 8.0; x += spacing) {
    for (double y = 2.0 + 0.5 * spacing; y < 8.0; y += spacing) {
      const Point2 d = Point2(x, y) - centre;
      if (d.squaredNorm() > 5.0) continue;
      for (const Point2& axis : axes) {
        if (std::abs(d.dot(axis)) <= 1.0 && std::abs(d.y() * axis.x() - d.x() * axis.y()) <= 2.0) {
          ++inside;
          break;
        }
      }
    }
  }
  const double expected = inside * spacing * spacing;
  EXPECT_NEAR(seenArea(seen), expected, 1e-3 * expected);
}

TEST(SeenArea, QuarterRotationMatchesIndependentUnionOfFootprints) {
  const FrustumSensor sensor(4.0, 2.0, 0.0);
  const Point2 centre(5.0, 5.0);
  const std::vector<Pose2> poses = waypointPathPoses({{centre.x() - 1.0, centre.y(), 0.0},
                                                      {centre.x(), centre.y(), 0.0},
                                                      {centre.x(), centre.y() + 1.0, 0.0}},
                                                     0.1);
  // Only the rotation's footprints at the middle waypoint, excluding the two legs.
  std::vector<Pose2> rotation;
  for (const Pose2& pose : poses) {
    if ((pose.position() - centre).norm() < 1e-12) rotation.push_back(pose);
  }
  ASSERT_EQ(rotation.size(), 17u);  // ceil((pi / 2) / 0.1) = 16 steps
  const CoverageRaster raster({0.0, 0.0}, 0.01, 1000, 1000);
  SeenArea seen(raster);
  seen.addTrajectory(rotation, sensor);
  // A point is seen when it lies in one of the rotated rectangles.
  std::vector<Point2> axes;
  for (const Pose2& pose : rotation) axes.emplace_back(std::cos(pose.yaw), std::sin(pose.yaw));
  const double spacing = 0.004;
  std::size_t inside = 0;
  for (double x = 2.0 + 0.5 * spacing; x < 8.0; x += spacing) {
    for (double y = 2.0 + 0.5 * spacing; y < 8.0; y += spacing) {
      const Point2 d = Point2(x, y) - centre;
      for (const Point2& axis : axes) {
        const double along = d.dot(axis);
        const double across = d.y() * axis.x() - d.x() * axis.y();
        if (std::abs(along) <= 1.0 && std::abs(across) <= 2.0) {
          ++inside;
          break;
        }
      }
    }
  }
  const double expected = inside * spacing * spacing;
  EXPECT_NEAR(seenArea(seen), expected, 1e-3 * expected);
}

// A path given as poses, rotations included, sees with addSweptPath exactly what the
// waypoint path it samples sees, and more than addTrajectory (the rotation's sectors).
TEST(SeenArea, SweptPathOfAWaypointPathSeesTheSameCells) {
  const FrustumSensor sensor(4.0, 2.0, 0.0);
  const CoverageRaster raster({0.0, 0.0}, 0.02, 1500, 1000);
  const std::vector<Pose2> waypoints{{5, 5, 0}, {20, 5, 0}, {20, 12, 0}, {8, 16, 0}};
  SeenArea expected(raster);
  expected.addWaypointPath(waypoints, sensor, 0.2);
  SeenArea swept(raster);
  swept.addSweptPath(waypointPathPoses(waypoints, 0.2), sensor);
  SeenArea unswept(raster);
  unswept.addTrajectory(waypointPathPoses(waypoints, 0.2), sensor);
  EXPECT_EQ(swept.seenMask(), expected.seenMask());
  EXPECT_GT(seenArea(swept), seenArea(unswept));
}

TEST(SeenArea, CircleTurnSeesAnnulus) {
  const FrustumSensor sensor(4.0, 2.0, 0.0);
  const CoverageRaster raster({26.0, 26.0}, 0.02, 2400, 2400);
  SeenArea seen(raster);
  seen.addTrajectory(circleArc({50.0, 50.0}, 20.0, 0.0, 2.0 * M_PI, 2001), sensor);
  // Inner radius R - W/2; outer radius reached by the outer corners.
  const double inner = 20.0 - 2.0;
  const double outer_squared = 22.0 * 22.0 + 1.0 * 1.0;
  const double expected = M_PI * (outer_squared - inner * inner);
  EXPECT_NEAR(seenArea(seen), expected, 1e-3 * expected);
}

TEST(SeenArea, SecondPassCountsAgain) {
  const FrustumSensor sensor(4.0, 2.0, 0.0);
  const CoverageRaster raster({0.0, 0.0}, 0.05, 1000, 1000);
  SeenArea seen(raster);
  // Out and back, turning in place at (40, 25).
  seen.addWaypointPath({{10, 25, 0}, {40, 25, 0}, {10, 25, 0}}, sensor, kDefaultRotationStep);
  EXPECT_EQ(seen.visits(cellAt(raster, {25.01, 25.01})), 2u);
  EXPECT_EQ(seen.visits(cellAt(raster, {25.01, 26.51})), 2u);
  EXPECT_EQ(seen.visits(cellAt(raster, {40.01, 25.01})), 1u);  // seen all through the turn
  EXPECT_EQ(seen.visits(cellAt(raster, {41.51, 25.01})), 1u);  // seen during the turn only
  EXPECT_EQ(seen.visits(cellAt(raster, {25.01, 28.01})), 0u);
  // A separate pass over the same place is another visit.
  seen.addTrajectory({{25.0, 25.0, 0.0}}, sensor);
  EXPECT_EQ(seen.visits(cellAt(raster, {25.01, 25.01})), 3u);
  const Heatmap heatmap = seen.heatmap();
  EXPECT_EQ(heatmap.columns, 1000);
  EXPECT_EQ(heatmap.rows, 1000);
  EXPECT_DOUBLE_EQ(heatmap.cell_size, 0.05);
  EXPECT_EQ(heatmap.visits[cellAt(raster, {25.01, 25.01})], 3u);
}

TEST(SeenArea, LawnmowerOverlapIsSeenTwice) {
  // Lanes 2.4 m apart with a 4 m wide footprint: 1.6 m strips seen by two lanes.
  const FrustumSensor sensor(4.0, 1.6, 0.4);
  const CoverageRaster raster({0.0, 0.0}, 0.05, 700, 700);
  SeenArea seen(raster);
  seen.addTrajectory(waypointPathPoses({{5, 5, 0}, {30, 5, 0}, {30, 7.4, 0}, {5, 7.4, 0}}), sensor);
  EXPECT_EQ(seen.visits(cellAt(raster, {17.51, 6.21})), 2u);  // in both lanes
  EXPECT_EQ(seen.visits(cellAt(raster, {17.51, 4.01})), 1u);  // first lane only
  EXPECT_EQ(seen.visits(cellAt(raster, {17.51, 8.81})), 1u);  // second lane only
  EXPECT_EQ(seen.visits(cellAt(raster, {30.01, 5.01})), 1u);  // seen all through the turn
  // Seen at the end of the first lane, not later in the turn, again on the short leg, not
  // early in the second turn, again from late in it on into the second lane.
  EXPECT_EQ(seen.visits(cellAt(raster, {30.01, 6.21})), 3u);
}

TEST(SeenArea, AVisitIsAStepThatSeesACellTheStepBeforeDidNot) {
  // Random poses (moves and turns on the spot, back and forth over the same ground): each
  // cell's visits against a cell-by-cell count of the steps, each the cells with centres in
  // the convex hull of its two footprints, or in either footprint for a turn on the spot.
  const FrustumSensor sensor(3.0, 1.2, 0.3);
  const CoverageRaster raster({0.0, 0.0}, 0.1, 200, 200);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> coordinate(6.0, 14.0);
  std::uniform_real_distribution<double> heading(-M_PI, M_PI);
  std::bernoulli_distribution turn_on_the_spot(0.3);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Pose2> poses{{coordinate(random), coordinate(random), heading(random)}};
    for (int k = 0; k < 30; ++k) {
      Pose2 next{coordinate(random), coordinate(random), heading(random)};
      if (turn_on_the_spot(random)) next = {poses.back().x, poses.back().y, heading(random)};
      poses.push_back(next);
    }
    SeenArea seen(raster);
    seen.addTrajectory(poses, sensor);

    std::vector<std::uint16_t> expected(raster.cellCount(), 0);
    std::set<std::size_t> before;
    for (std::size_t i = 1; i < poses.size(); ++i) {
      const Ring a = sensor.footprint(poses[i - 1]);
      const Ring b = sensor.footprint(poses[i]);
      std::vector<CellSpan> spans;
      if (poses[i].position() == poses[i - 1].position()) {
        raster.appendConvexSpans(a, spans);
        raster.appendConvexSpans(b, spans);
      } else {
        std::vector<Point2> corners(a.begin(), a.end());
        corners.insert(corners.end(), b.begin(), b.end());
        raster.appendConvexSpans(convexHull(corners), spans);
      }
      std::set<std::size_t> step;
      for (const CellSpan& span : spans) {
        for (int column = span.begin; column < span.end; ++column) {
          step.insert(raster.index(span.row, column));
        }
      }
      for (const std::size_t cell : step) {
        if (before.count(cell) == 0) ++expected[cell];
      }
      before = std::move(step);
    }
    std::size_t differing = 0;
    for (std::size_t i = 0; i < raster.cellCount(); ++i) {
      if (seen.visits(i) != expected[i]) ++differing;
    }
    EXPECT_EQ(differing, 0u) << "trial " << trial;
  }
}

TEST(SeenArea, HeatmapDoesNotDependOnSamplingDensity) {
  const FrustumSensor sensor(3.0, 1.0, 0.0);
  const CoverageRaster raster({0.0, 0.0}, 0.05, 800, 800);
  // A straight leg, then one and a half turns around a circle: the first half of the
  // circle is passed twice.
  const auto trajectory = [](int density) {
    std::vector<Pose2> poses = straightLeg({5.0, 20.0}, {20.0, 20.0}, 3 * density);
    poses.pop_back();
    const std::vector<Pose2> arc =
        circleArc({20.0, 30.0}, 10.0, -0.5 * M_PI, 2.5 * M_PI, 150 * density);
    poses.insert(poses.end(), arc.begin(), arc.end());
    return poses;
  };
  SeenArea sparse(raster);
  sparse.addTrajectory(trajectory(1), sensor);
  SeenArea dense(raster);
  dense.addTrajectory(trajectory(10), sensor);
  std::size_t seen_cells = 0;
  std::size_t differing = 0;
  for (std::size_t i = 0; i < raster.cellCount(); ++i) {
    if (sparse.seen(i) || dense.seen(i)) ++seen_cells;
    if (sparse.visits(i) != dense.visits(i)) ++differing;
  }
  ASSERT_GT(seen_cells, 0u);
  // Only a thin rim differs: the chords of the sparse arc, and points just beyond the
  // footprint's outer edge, which the dense arc sees twice per pass (front and back
  // corner) as the continuous motion does.
  EXPECT_LT(static_cast<double>(differing) / seen_cells, 1e-2);
  for (const SeenArea* seen : {&sparse, &dense}) {
    EXPECT_EQ(seen->visits(cellAt(raster, {12.51, 20.01})), 1u);  // the straight leg
    EXPECT_EQ(seen->visits(cellAt(raster, {30.01, 30.01})), 2u);  // passed twice
    EXPECT_EQ(seen->visits(cellAt(raster, {10.01, 30.01})), 1u);  // passed once
  }
}

TEST(SeenArea, StraightLegResampledGivesIdenticalHeatmap) {
  const FrustumSensor sensor(3.0, 1.0, 0.0);
  const CoverageRaster raster({0.0, 0.0}, 0.05, 600, 600);
  SeenArea sparse(raster);
  sparse.addTrajectory(straightLeg({3.0, 4.0}, {25.0, 21.0}, 5), sensor);
  SeenArea dense(raster);
  dense.addTrajectory(straightLeg({3.0, 4.0}, {25.0, 21.0}, 50), sensor);
  std::size_t differing = 0;
  for (std::size_t i = 0; i < raster.cellCount(); ++i) {
    differing += sparse.visits(i) != dense.visits(i) ? 1 : 0;
  }
  // Equal but for centres within rounding of the shared edges.
  EXPECT_LE(differing, 5u);
  EXPECT_NEAR(seenArea(dense), 3.0 * ((Point2(25.0, 21.0) - Point2(3.0, 4.0)).norm() + 1.0), 0.1);
}

TEST(SeenArea, CoverageOfRegionAndUnseenCells) {
  const FrustumSensor sensor(2.0, 2.0, 0.0);
  const CoverageRaster raster({0.0, 0.0}, 0.5, 20, 20);
  CellMask region(raster.cellCount(), 0);
  for (int row = 0; row < 4; ++row) {
    for (int column = 0; column < 8; ++column) region[raster.index(row, column)] = 1;
  }
  SeenArea seen(raster);
  seen.addTrajectory({{1.0, 1.0, 0.0}}, sensor);  // the cells of [0, 2] x [0, 2]
  EXPECT_DOUBLE_EQ(seen.coveragePercent(region), 50.0);
  const std::vector<Point2> unseen = seen.unseenCentres(region, 100);
  EXPECT_EQ(unseen.size(), 16u);
  for (const Point2& centre : unseen) EXPECT_GT(centre.x(), 2.0);
  EXPECT_EQ(seen.unseenCentres(region, 3).size(), 3u);
  EXPECT_THROW(seen.coveragePercent(CellMask(raster.cellCount(), 0)), InvalidInputError);
  EXPECT_THROW(seen.coveragePercent(CellMask(3, 1)), InvalidInputError);
}

TEST(SeenArea, DegenerateTrajectories) {
  const CoverageRaster raster({0.0, 0.0}, 0.1, 100, 100);
  SeenArea seen(raster);
  seen.addTrajectory({}, FrustumSensor(2.0, 1.0, 0.0));
  EXPECT_EQ(CoverageRaster::countCells(seen.seenMask()), 0u);
  // A line sensor standing still sees nothing; moving, it sweeps its width.
  seen.addTrajectory({{5.0, 5.0, 0.0}, {5.0, 5.0, 1.0}}, FrustumSensor(2.0, 0.0, 0.0));
  EXPECT_EQ(CoverageRaster::countCells(seen.seenMask()), 0u);
  seen.addTrajectory({{2.0, 5.0, 0.0}, {8.0, 5.0, 0.0}}, FrustumSensor(2.0, 0.0, 0.0));
  EXPECT_NEAR(raster.area(seen.seenMask()), 12.0, 1e-9);
  // Moving sideways along the line sensor's own line: a segment, no area.
  SeenArea sideways(raster);
  sideways.addTrajectory({{5.0, 2.0, 0.0}, {5.0, 8.0, 0.0}}, FrustumSensor(2.0, 0.0, 0.0));
  EXPECT_EQ(CoverageRaster::countCells(sideways.seenMask()), 0u);
  // Footprints off the grid are clipped.
  SeenArea outside(raster);
  outside.addTrajectory({{-50.0, -50.0, 0.0}, {50.0, -50.0, 0.0}}, FrustumSensor(2.0, 1.0, 0.0));
  EXPECT_EQ(CoverageRaster::countCells(outside.seenMask()), 0u);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(seen.addTrajectory({{1.0, 1.0, 0.0}, {nan, 1.0, 0.0}}, FrustumSensor(2, 1, 0)),
               InvalidInputError);
  EXPECT_THROW(seen.addTrajectory({{1.0, 1.0, std::numeric_limits<double>::infinity()}},
                                  FrustumSensor(2, 1, 0)),
               InvalidInputError);
}

}  // namespace
}  // namespace kinematic_coverage::core
