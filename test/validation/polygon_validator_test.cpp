#include "polygon_coverage_ros_bridge/validation/polygon_validator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "test/support/invalid_input_message.h"
#include "test/support/random_polygons.h"

namespace kinematic_coverage::core {
namespace {

Ring square(double x0, double y0, double size) {
  return {{x0, y0}, {x0 + size, y0}, {x0 + size, y0 + size}, {x0, y0 + size}};
}

using testing::invalidInputMessage;

std::string validationError(const PolygonWithHoles& polygon) {
  return invalidInputMessage([&] { PolygonValidator().validate(polygon); });
}

TEST(PolygonValidator, AcceptsValidPolygonsInEitherOrientation) {
  PolygonWithHoles polygon{square(0, 0, 30), {square(8, 8, 4)}};
  EXPECT_EQ(validationError(polygon), "");
  std::reverse(polygon.hull.begin(), polygon.hull.end());
  EXPECT_EQ(validationError(polygon), "");
}

TEST(PolygonValidator, AcceptsDuplicateConsecutiveAndClosingVertices) {
  PolygonWithHoles polygon{{{0, 0}, {0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}}, {}};
  EXPECT_EQ(validationError(polygon), "");
}

TEST(PolygonValidator, RejectsTooFewDistinctVertices) {
  EXPECT_EQ(validationError({{{0, 0}, {1, 0}}, {}}),
            "hull has 2 distinct vertices: a ring needs at least 3");
  EXPECT_EQ(validationError({square(0, 0, 10), {{{1, 1}, {2, 1}, {2, 1}, {1, 1}}}}),
            "hole 0 has 2 distinct vertices: a ring needs at least 3");
  EXPECT_EQ(validationError({{}, {}}), "hull has 0 distinct vertices: a ring needs at least 3");
}

TEST(PolygonValidator, RejectsZeroArea) {
  EXPECT_EQ(validationError({{{0, 0}, {1, 1}, {2, 2}, {3, 3}}, {}}),
            "hull has zero area: all its vertices lie on one line");
  EXPECT_EQ(validationError({square(0, 0, 10), {square(1, 1, 1), {{2, 5}, {4, 5}, {3, 5}}}}),
            "hole 1 has zero area: all its vertices lie on one line");
}

TEST(PolygonValidator, RejectsSliversThinnerThanTheRouteTolerance) {
  // Found by planner_fuzzer: a triangle whose first two vertices are 5.6e-14 m apart has a
  // non-zero exact area, but the route stage (tolerance 1e-9 of the hull's extent) sees a
  // line, and planning failed on it.
  const std::string hull_error = validationError(
      {{{-5, -5}, {-5, -4.999999999999944}, {13.977287313476129, 34.72168021276061}}, {}});
  EXPECT_EQ(hull_error.rfind("hull is a sliver: its mean width", 0), 0u) << hull_error;
  EXPECT_NE(hull_error.find("is below 3.972168021e-08 m"), std::string::npos) << hull_error;
  const std::string hole_error =
      validationError({square(0, 0, 10), {square(1, 1, 1), {{2, 5}, {4, 5}, {3, 5 + 1e-12}}}});
  EXPECT_EQ(hole_error.rfind("hole 1 is a sliver", 0), 0u) << hole_error;
  // A thin ring well above the tolerance is valid.
  EXPECT_EQ(validationError({square(0, 0, 10), {{{2, 5}, {4, 5}, {3, 5 + 1e-6}}}}), "");
}

TEST(PolygonValidator, NamesTheCrossingEdgesOfABowtie) {
  EXPECT_EQ(validationError({{{0, 0}, {2, 2}, {2, 0}, {0, 2}}, {}}),
            "hull is self-intersecting: edge 0 (vertices 0-1) and edge 2 (vertices 2-3) meet "
            "at (1, 1)");
}

TEST(PolygonValidator, NamesARepeatedVertex) {
  const Ring pinched = {{0, 0}, {2, 0}, {1, 1}, {2, 2}, {0, 2}, {1, 1}};
  const std::string message = validationError({square(-5, -5, 20), {square(6, 6, 1), pinched}});
  EXPECT_EQ(message.rfind("hole 1 is self-intersecting: vertices ", 0), 0u) << message;
  EXPECT_NE(message.find("coincide at (1, 1)"), std::string::npos) << message;
}

TEST(PolygonValidator, NamesAFoldBack) {
  EXPECT_EQ(validationError({{{0, 0}, {4, 0}, {4, 4}, {4, 2}}, {}}),
            "hull is self-intersecting: its edges fold back onto each other at vertex 2 (4, 4)");
}

TEST(PolygonValidator, NamesOverlappingEdges) {
  // Edge 1 runs along the x axis back over edge 4.
  const Ring ring = {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 0}, {2, 0}, {2, -1}, {0, -1}};
  const std::string message = validationError({ring, {}});
  EXPECT_EQ(message.rfind("hull is self-intersecting: ", 0), 0u) << message;
}

TEST(PolygonValidator, RejectsNonFiniteAndHugeCoordinates) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(validationError({{{0, 0}, {nan, 0}, {1, 1}}, {}}),
            "hull vertex 1: the x coordinate nan is not finite");
  EXPECT_EQ(validationError({square(0, 0, 10), {{{1, 1}, {2, 1}, {2, -inf}}}}),
            "hole 0 vertex 2: the y coordinate -inf is not finite");
  const std::string message = validationError({{{0, 0}, {1e9, 0}, {1, 1}}, {}});
  EXPECT_NE(message.find("hull vertex 1: the x coordinate 1000000000 exceeds the limit"),
            std::string::npos)
      << message;
}

TEST(PolygonValidator, RejectsAHoleEntirelyOutsideTheHull) {
  EXPECT_EQ(validationError({square(0, 0, 10), {square(2, 2, 2), square(20, 20, 2)}}),
            "hole 1 lies entirely outside the hull");
  // Touching the hull from outside along an edge is still outside.
  EXPECT_EQ(validationError({square(0, 0, 10), {square(10, 2, 3)}}),
            "hole 0 lies entirely outside the hull");
  // Inside a concave notch of the hull, inside its bounding box.
  const Ring u = {{0, 0}, {10, 0}, {10, 10}, {7, 10}, {7, 3}, {3, 3}, {3, 10}, {0, 10}};
  EXPECT_EQ(validationError({u, {square(4, 5, 2)}}), "hole 0 lies entirely outside the hull");
}

TEST(PolygonValidator, AcceptsHolesCrossingOrCoveringTheHull) {
  // A bar with every vertex outside the hull still crosses it.
  EXPECT_EQ(validationError({square(0, 0, 10), {{{-1, 4}, {11, 4}, {11, 5}, {-1, 5}}}}), "");
  EXPECT_EQ(validationError({square(0, 0, 10), {square(-1, -1, 12)}}), "");
}

TEST(PolygonValidator, EnforcesTheSizeLimits) {
  PolygonWithHoles many_holes{square(0, 0, 1e4), {}};
  for (std::size_t i = 0; i <= kMaxHoles; ++i) many_holes.holes.push_back(square(1, 1, 1));
  EXPECT_EQ(validationError(many_holes), "the polygon has 5001 holes, more than the limit of 5000");
  PolygonWithHoles many_vertices;
  for (std::size_t i = 0; i <= kMaxTotalVertices; ++i) {
    const double angle = 2 * M_PI * i / (kMaxTotalVertices + 1);
    many_vertices.hull.emplace_back(std::cos(angle), std::sin(angle));
  }
  EXPECT_EQ(validationError(many_vertices),
            "the polygon has 100001 vertices in total, more than the limit of 100000");
}

TEST(PolygonValidator, ChecksStartAndGoal) {
  const PolygonWithHoles polygon{square(0, 0, 30), {square(1, 1, 2), square(8, 8, 4)}};
  const PolygonValidator validator;
  EXPECT_EQ(invalidInputMessage([&] {
              validator.validateEndpoint("start", {10, 10}, polygon);
            }),
            "start (10, 10) lies inside hole 1");
  EXPECT_EQ(invalidInputMessage([&] {
              validator.validateEndpoint("goal", {2.5, 1.5}, polygon);
            }),
            "goal (2.5, 1.5) lies inside hole 0");
  EXPECT_EQ(invalidInputMessage([&] {
              validator.validateEndpoint("start", {8, 10}, polygon);
            }),
            "");
  EXPECT_EQ(invalidInputMessage([&] {
              validator.validateEndpoint("start", {-5, 40}, polygon);
            }),
            "");
  EXPECT_EQ(invalidInputMessage([&] { validator.validateEndpoint("goal", {5, 5}, polygon); }), "");
  EXPECT_EQ(invalidInputMessage([&] {
              validator.validateEndpoint("goal", {std::nan(""), 5}, polygon);
            }),
            "goal (nan, 5): the x coordinate nan is not finite");
}

/// Brute force: exact for small integer coordinates.
bool segmentsMeet(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  auto orient = [](const Point2& p, const Point2& q, const Point2& r) {
    const double v = cross(p, q, r);
    return (v > 0) - (v < 0);
  };
  auto onSegment = [](const Point2& p, const Point2& q, const Point2& r) {
    return std::min(p.x(), q.x()) <= r.x() && r.x() <= std::max(p.x(), q.x()) &&
           std::min(p.y(), q.y()) <= r.y() && r.y() <= std::max(p.y(), q.y());
  };
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && onSegment(a, b, c)) || (o2 == 0 && onSegment(a, b, d)) ||
         (o3 == 0 && onSegment(c, d, a)) || (o4 == 0 && onSegment(c, d, b));
}

bool bruteForceSimple(Ring ring) {
  Ring r;
  for (const Point2& p : ring) {
    if (r.empty() || r.back() != p) r.push_back(p);
  }
  while (r.size() > 1 && r.back() == r.front()) r.pop_back();
  const std::size_t n = r.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point2 &a = r[i], &b = r[(i + 1) % n], &c = r[(i + 2) % n];
    if (cross(a, b, c) == 0 && (a - b).dot(c - b) > 0) return false;  // fold back
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      if (segmentsMeet(r[i], r[(i + 1) % n], r[j], r[(j + 1) % n])) return false;
    }
  }
  return true;
}

TEST(PolygonValidator, AgreesWithBruteForceOnRandomGridRings) {
  std::mt19937 rng(12345);
  std::uniform_int_distribution<int> coordinate(0, 4);
  std::uniform_int_distribution<int> size(3, 7);
  int simple = 0, rejected = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    Ring ring;
    const int n = size(rng);
    for (int i = 0; i < n; ++i) ring.emplace_back(coordinate(rng), coordinate(rng));
    const std::string message = validationError({ring, {}});
    if (message.find("distinct vertices") != std::string::npos ||
        message.find("zero area") != std::string::npos) {
      continue;
    }
    const bool expected_simple = bruteForceSimple(ring);
    EXPECT_EQ(message.empty(), expected_simple) << trial << ": " << message;
    if (!message.empty()) {
      EXPECT_EQ(message.rfind("hull is self-intersecting: ", 0), 0u) << message;
      EXPECT_EQ(message.find("its edges intersect"), std::string::npos) << message;
    }
    (expected_simple ? simple : rejected)++;
  }
  EXPECT_GT(simple, 100);
  EXPECT_GT(rejected, 100);
}

TEST(PolygonValidator, AcceptsRandomMaps) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 100; ++trial) {
    const PolygonWithHoles map = testing::randomMap(rng, 100.0, 10, 1.0);
    EXPECT_EQ(validationError(map), "") << trial;
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
