#pragma once
// Fuzzed corners, waypoint paths and obstacles for the smoothing fuzz targets
// (corner_smoothing_fuzzer, coverage_preserving_fuzzer), and the properties every smoothed
// path must have:
// - continuity: consecutive primitives join in position and heading (kJoinPositionTolerance,
//   kJoinHeadingTolerance of primitive_path_validation.h; validatePrimitivePath), from the
//   first waypoint to the last;
// - curvature at most 1 / the least radius the strategy may use;
// - statistics that add up, and arcs off every hull and hole edge and inside the free area.

#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "fuzz/fuzz_check.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "trajectory_generation_tools/path/path_primitive.h"
#include "trajectory_generation_tools/smoothing/global_smoothing_options.h"
#include "trajectory_generation_tools/smoothing/path_smoother.h"
#include "trajectory_generation_tools/trajectory/primitive_distance.h"
#include "trajectory_generation_tools/trajectory/primitive_path_metrics.h"
#include "trajectory_generation_tools/trajectory/primitive_path_validation.h"

namespace kinematic_coverage::fuzz {

using core::GlobalSmoothingOptions;
using core::InvalidInputError;
using core::kJoinHeadingTolerance;
using core::kJoinPositionTolerance;
using core::PathPrimitive;
using core::Point2;
using core::PolygonWithHoles;
using core::PrimitiveKind;
using core::Ring;
using core::SmoothedPath;

/// Waypoints lie in [-kBox, kBox]^2; holes in the quadrants of [-kHoleBox, kHoleBox]^2.
inline constexpr double kBox = 50.0;
inline constexpr double kHoleBox = 40.0;
/// Coordinates snap to this grid (m) when the input asks for it, to provoke collinear
/// legs, reversals and A == B.
inline constexpr double kSnapGrid = 0.5;
/// Relative slack of the curvature bound (arcs are built with radius r exactly).
inline constexpr double kCurvatureSlack = 1e-12;

/// A waypoint in [-kBox, kBox]^2, snapped to kSnapGrid when `snap`.
inline Point2 point(FuzzedDataProvider& input, bool snap) {
  Point2 p(input.ConsumeFloatingPointInRange(-kBox, kBox),
           input.ConsumeFloatingPointInRange(-kBox, kBox));
  if (snap) p = (p / kSnapGrid).array().round().matrix() * kSnapGrid;
  return p;
}

/// A star-shaped ring about `centre`: vertex i at angle (i + jitter) * 2 pi / n with
/// jitter in [0, 0.5), so consecutive angles differ by less than pi and the ring is simple.
inline Ring starRing(FuzzedDataProvider& input, const Point2& centre, int vertices,
                     double min_radius, double max_radius) {
  Ring ring;
  const double step = 2.0 * M_PI / vertices;
  for (int i = 0; i < vertices; ++i) {
    const double angle = step * (i + input.ConsumeFloatingPointInRange(0.0, 0.5));
    const double radius = input.ConsumeFloatingPointInRange(min_radius, max_radius);
    ring.push_back(centre + radius * Point2(std::cos(angle), std::sin(angle)));
  }
  return ring;
}

/// Hull (optional; at least 72 m from the origin, past every hole) and up to four holes,
/// one per quadrant of [-40, 40]^2, at most 9.5 m across their centre.
inline PolygonWithHoles obstacles(FuzzedDataProvider& input) {
  PolygonWithHoles area;
  if (input.ConsumeBool()) {
    area.hull =
        starRing(input, Point2::Zero(), input.ConsumeIntegralInRange<int>(8, 16), 72.0, 100.0);
  }
  const int holes = input.ConsumeIntegralInRange<int>(0, 4);
  for (int i = 0; i < holes; ++i) {
    const Point2 quadrant((i % 2 == 0 ? 1.0 : -1.0) * kHoleBox / 2,
                          (i < 2 ? 1.0 : -1.0) * kHoleBox / 2);
    const Point2 centre = quadrant + Point2(input.ConsumeFloatingPointInRange(-10.0, 10.0),
                                            input.ConsumeFloatingPointInRange(-10.0, 10.0));
    const double size = input.ConsumeFloatingPointInRange(0.05, 9.5);
    area.holes.push_back(
        starRing(input, centre, input.ConsumeIntegralInRange<int>(3, 6), 0.1 * size, size));
  }
  return area;
}

/// True when p lies in the free area (an empty hull: the unbounded plane).
inline bool inFreeArea(const PolygonWithHoles& area, const Point2& p) {
  if (!area.hull.empty() && !core::insideRing(p, area.hull)) return false;
  for (const Ring& hole : area.holes) {
    if (core::insideRing(p, hole)) return false;
  }
  return true;
}

/// Aborts unless `primitive` keeps off every edge and (sampled at its middle) lies in the
/// free area: the collision freedom that feasibility promised.
inline void checkClear(const PolygonWithHoles& area, const PathPrimitive& primitive,
                       const std::string& what) {
  auto check_ring = [&](const Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const double distance =
          core::distancePrimitiveToSegment(primitive, ring[i], ring[(i + 1) % ring.size()]);
      fuzzCheck(distance > 0.0, what + " touches or crosses an obstacle edge");
    }
  };
  if (!area.hull.empty()) check_ring(area.hull);
  for (const Ring& hole : area.holes) check_ring(hole);
  fuzzCheck(inFreeArea(area, primitive.poseAt(0.5).position()), what + " lies in an obstacle");
}

/// The absolute difference of two headings, wrapped to [0, pi].
inline double headingGap(double a, double b) { return std::abs(core::wrapAngle(a - b)); }

/// The properties of a smoothed waypoint path whose arcs have radii of at least
/// `min_radius`.
inline void checkSmoothedPath(const PolygonWithHoles& area, const std::vector<Point2>& waypoints,
                              double min_radius, const SmoothedPath& path) {
  const auto& primitives = path.primitives;
  try {
    core::validatePrimitivePath(primitives);
  } catch (const InvalidInputError& error) {
    fuzzCheck(false, std::string("smoothed path is not continuous: ") + error.what());
  }
  fuzzCheck(core::primitivePathMaxCurvature(primitives) <= (1.0 + kCurvatureSlack) / min_radius,
            "path curvature above 1 / radius");
  const auto& statistics = path.statistics;
  fuzzCheck(statistics.turns_smoothed == statistics.inner + statistics.outer_bisector +
                                             statistics.outer_tangent + statistics.reverse_curve +
                                             statistics.bulb &&
                statistics.turns_smoothed <= statistics.turns_total,
            "smoothing statistics do not add up");
  if (primitives.empty()) return;
  fuzzCheck((primitives.front().start() - waypoints.front()).norm() <= kJoinPositionTolerance,
            "path does not start at the first waypoint");
  fuzzCheck((primitives.back().end() - waypoints.back()).norm() <= kJoinPositionTolerance,
            "path does not end at the last waypoint");
  std::optional<double> heading;  // end heading of the last primitive with a heading
  for (std::size_t i = 0; i < primitives.size(); ++i) {
    const PathPrimitive& primitive = primitives[i];
    if (primitive.kind() == PrimitiveKind::kArc) {
      checkClear(area, primitive, "path arc " + std::to_string(i));
    }
    // Only a point-like segment has no heading of its own. Arcs keep theirs however short:
    // one of kDegenerateLength on a radius r turns by up to kDegenerateLength / r, and
    // skipping it would report that turn as a jump.
    if (primitive.kind() == PrimitiveKind::kSegment && core::isDegenerate(primitive)) {
      continue;
    }
    if (heading) {
      fuzzCheck(headingGap(*heading, primitive.startPose().yaw) <= kJoinHeadingTolerance,
                "heading jumps by " +
                    std::to_string(headingGap(*heading, primitive.startPose().yaw)) +
                    " rad into primitive " + std::to_string(i));
    }
    heading = primitive.endPose().yaw;
  }
}

/// The global smoothing strategy's options without a preserved sensor: the corner's
/// radius as turning_radius, a smaller or equal min_turning_radius and a velocity model.
inline GlobalSmoothingOptions globalOptions(FuzzedDataProvider& input, double radius) {
  GlobalSmoothingOptions options;
  options.vehicle.turning_radius = radius;
  options.min_turning_radius = radius * input.ConsumeFloatingPointInRange(0.1, 1.0);
  options.vehicle.v_max = input.ConsumeFloatingPointInRange(0.05, 3.0);
  options.vehicle.a_max = input.ConsumeFloatingPointInRange(0.05, 2.0);
  options.vehicle.yaw_rate_max = input.ConsumeFloatingPointInRange(0.05, 2.0);
  return options;
}

}  // namespace kinematic_coverage::fuzz
