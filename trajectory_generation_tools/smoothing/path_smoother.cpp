#include "trajectory_generation_tools/smoothing/path_smoother.h"

#include <cmath>
#include <string>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "trajectory_generation_tools/smoothing/corner_geometry.h"
#include "trajectory_generation_tools/smoothing/corner_smoother.h"

namespace kinematic_coverage::core {
namespace {

/// Joining segments no longer than this (m) are left out; the next primitive then starts
/// within this distance of the previous one's end.
constexpr double kMinSegmentLength = 1e-9;

/// The waypoints without duplicates and without straight interior waypoints.
std::vector<Point2> cornerWaypoints(const std::vector<Point2>& waypoints) {
  std::vector<Point2> distinct;
  distinct.reserve(waypoints.size());
  for (const Point2& p : waypoints) {
    if (!p.allFinite()) throw InvalidInputError("waypoint with a non-finite coordinate");
    if (distinct.empty() || (p - distinct.back()).norm() > kDuplicateWaypointDistance) {
      distinct.push_back(p);
    }
  }
  if (distinct.size() < 3) return distinct;
  std::vector<Point2> corners{distinct.front()};
  for (std::size_t i = 1; i + 1 < distinct.size(); ++i) {
    const Point2 in = distinct[i] - corners.back();
    const Point2 out = distinct[i + 1] - distinct[i];
    const double turn = std::atan2(std::abs(in.x() * out.y() - in.y() * out.x()), in.dot(out));
    if (turn > kStraightTurnTolerance) corners.push_back(distinct[i]);
  }
  corners.push_back(distinct.back());
  return corners;
}

}  // namespace

PathSmoother::PathSmoother(const PolygonWithHoles& free_area, double turning_radius)
    : index_(free_area), radius_(turning_radius) {
  if (!std::isfinite(turning_radius) || turning_radius <= 0.0) {
    throw InvalidInputError("turning_radius must be a positive finite number, got " +
                            std::to_string(turning_radius));
  }
}

SmoothedPath PathSmoother::smooth(const std::vector<Point2>& waypoints) const {
  return build(waypoints);
}

SmoothedPath PathSmoother::smooth(const std::vector<Pose2>& waypoints) const {
  std::vector<Point2> points;
  points.reserve(waypoints.size());
  for (const Pose2& pose : waypoints) points.push_back(pose.position());
  return build(points);
}

SmoothedPath PathSmoother::build(const std::vector<Point2>& waypoints) const {
  const std::vector<Point2> points = cornerWaypoints(waypoints);
  SmoothedPath path;
  if (points.size() < 2) return path;
  path.primitives.reserve(2 * points.size());
  const CornerSmoother smoother(index_);
  SmoothingStatistics& statistics = path.statistics;

  Point2 current = points.front();  // where the path built so far ends
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    const Point2& b = points[i];
    const Point2 incoming = (b - points[i - 1]).normalized();
    ++statistics.turns_total;
    const Corner corner{current, b, points[i + 1], radius_, incoming};
    const std::optional<CornerSmoothing> smoothed = smoother.smooth(corner);
    if (smoothed) {
      // The joining segment runs along the leg's exact direction, so that its heading
      // matches the first arc's even when it is short.
      const double length = (smoothed->arcs.front().start() - current).dot(incoming);
      if (length > kMinSegmentLength) {
        path.primitives.push_back(PathPrimitive::segment(current, current + length * incoming));
      }
      path.primitives.insert(path.primitives.end(), smoothed->arcs.begin(), smoothed->arcs.end());
      current = smoothed->arcs.back().end();
      ++statistics.turns_smoothed;
      switch (smoothed->variant) {
        case SmoothingVariant::kInner:
          ++statistics.inner;
          break;
        case SmoothingVariant::kOuterBisector:
          ++statistics.outer_bisector;
          break;
        case SmoothingVariant::kOuterTangent:
          ++statistics.outer_tangent;
          break;
        case SmoothingVariant::kNone:
          break;
      }
      continue;
    }
    const double length = (b - current).dot(incoming);
    if (length > kMinSegmentLength) {
      path.primitives.push_back(PathPrimitive::segment(current, current + length * incoming));
    }
    const Point2 outgoing = (points[i + 1] - b).normalized();
    const double turn = std::atan2(incoming.x() * outgoing.y() - incoming.y() * outgoing.x(),
                                   incoming.dot(outgoing));
    path.primitives.push_back(
        PathPrimitive::rotation(b, std::atan2(incoming.y(), incoming.x()), turn));
    current = b;
  }
  const Point2 outgoing = (points.back() - points[points.size() - 2]).normalized();
  const double length = (points.back() - current).dot(outgoing);
  if (length > kMinSegmentLength) {
    path.primitives.push_back(PathPrimitive::segment(current, current + length * outgoing));
  }
  return path;
}

}  // namespace kinematic_coverage::core
