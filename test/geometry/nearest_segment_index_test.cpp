#include "polygon_coverage_ros_bridge/geometry/nearest_segment_index.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// The nearest segment by a scan in index order (the first of equally near ones).
NearestSegmentIndex::Nearest scan(const std::vector<Point2>& starts,
                                  const std::vector<Point2>& ends, const Point2& query) {
  NearestSegmentIndex::Nearest best{std::numeric_limits<double>::infinity(), 0};
  for (std::size_t s = 0; s < starts.size(); ++s) {
    const double d = distanceToSegment(query, starts[s], ends[s]);
    if (d < best.distance) best = {d, static_cast<std::uint32_t>(s)};
  }
  return best;
}

TEST(NearestSegmentIndexTest, FindsTheSegmentThatAScanFindsForRandomRings) {
  // Jagged rings sharing their vertices between consecutive edges (every vertex is the
  // nearest point of two edges at once) and a few far-apart clusters of them, with queries
  // near the rings, on their vertices and far away.
  std::mt19937 random(20261129);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Point2> starts, ends;
    const int rings = 1 + trial % 4;
    for (int r = 0; r < rings; ++r) {
      const Point2 centre(300.0 * r * unit(random), 50.0 * unit(random));
      const int n = 3 + 40 * trial;
      std::vector<Point2> ring;
      for (int i = 0; i < n; ++i) {
        const double angle = 2.0 * M_PI * i / n;
        const double radius = 10.0 + 4.0 * unit(random);
        ring.push_back(centre + radius * Point2(std::cos(angle), std::sin(angle)));
      }
      for (int i = 0; i < n; ++i) {
        starts.push_back(ring[i]);
        ends.push_back(ring[(i + 1) % n]);
      }
    }
    const NearestSegmentIndex index(starts, ends);
    std::vector<Point2> queries;
    for (int q = 0; q < 200; ++q) {
      queries.emplace_back(-100.0 + 1100.0 * unit(random), -100.0 + 300.0 * unit(random));
    }
    for (std::size_t s = 0; s < starts.size(); s += 7) queries.push_back(starts[s]);
    for (std::size_t s = 0; s < starts.size(); s += 5) {
      queries.push_back(starts[s] + 0.3 * Point2(unit(random) - 0.5, unit(random) - 0.5));
    }
    for (const Point2& query : queries) {
      const NearestSegmentIndex::Nearest expected = scan(starts, ends, query);
      const NearestSegmentIndex::Nearest found = index.nearest(query);
      EXPECT_EQ(found.distance, expected.distance);
      EXPECT_EQ(found.segment, expected.segment);
    }
  }
}

TEST(NearestSegmentIndexTest, PointSegmentsAndOneSegment) {
  const NearestSegmentIndex point({Point2(1, 1)}, {Point2(1, 1)});
  EXPECT_DOUBLE_EQ(point.nearest(Point2(4, 5)).distance, 5.0);
  const NearestSegmentIndex one({Point2(0, 0)}, {Point2(10, 0)});
  EXPECT_DOUBLE_EQ(one.nearest(Point2(5, -3)).distance, 3.0);
  EXPECT_DOUBLE_EQ(one.nearest(Point2(-1e6, 0)).distance, 1e6);
}

TEST(NearestSegmentIndexTest, RefusesNoSegmentsAndNonFiniteOnes) {
  EXPECT_THROW(NearestSegmentIndex({}, {}), InvalidInputError);
  EXPECT_THROW(NearestSegmentIndex({Point2(0, 0)}, {}), InvalidInputError);
  EXPECT_THROW(NearestSegmentIndex({Point2(0, 0)}, {Point2(NAN, 0)}), InvalidInputError);
}

}  // namespace
}  // namespace kinematic_coverage::core
