#include "trajectory_generation_tools/trajectory/trajectory_generator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "trajectory_generation_tools/smoothing/corner_waypoints.h"
#include "trajectory_generation_tools/smoothing/global_path_smoother.h"
#include "trajectory_generation_tools/smoothing/path_coverage_check.h"
#include "trajectory_generation_tools/trajectory/primitive_path_metrics.h"
#include "trajectory_generation_tools/trajectory/segment_path_builder.h"
#include "trajectory_generation_tools/trajectory/trajectory_sampler.h"
#include "trajectory_generation_tools/trajectory/trajectory_timing.h"

namespace kinematic_coverage::core {
namespace {

/// A primitive's ends count as in the free area within this distance (metres).
constexpr double kInsideTolerance = 1e-6;

/// turns_total of a segment path: its rotations that turn.
SmoothingStatistics segmentPathStatistics(const std::vector<PathPrimitive>& path) {
  SmoothingStatistics statistics;
  statistics.turns_total =
      static_cast<int>(std::count_if(path.begin(), path.end(), [](const PathPrimitive& p) {
        return p.kind() == PrimitiveKind::kRotation && p.turnAngle() > 0.0;
      }));
  return statistics;
}

/// The pieces of `primitive` off the leg [a, b]: none for a rotation on it, the parts of a
/// segment along the leg's line beyond the leg's ends (smoothing merges a leg with the
/// collinear leg before it), and any other primitive whole.
std::vector<PathPrimitive> offLeg(const PathPrimitive& primitive, const Point2& a,
                                  const Point2& b) {
  if (primitive.kind() == PrimitiveKind::kRotation) {
    if (distanceToSegment(primitive.start(), a, b) <= kInsideTolerance) return {};
    return {primitive};
  }
  const Point2 from = primitive.start();
  const Point2 direction = primitive.end() - from;
  const double length_sq = direction.squaredNorm();
  const Point2 leg = b - a;
  const double leg_length = leg.norm();
  const auto off_line = [&](const Point2& p) {
    const Point2 d = p - a;
    return std::abs(leg.x() * d.y() - leg.y() * d.x()) / leg_length > kInsideTolerance;
  };
  if (primitive.kind() != PrimitiveKind::kSegment || !(length_sq > 0.0) || !(leg_length > 0.0) ||
      off_line(from) || off_line(primitive.end())) {
    return {primitive};
  }
  const double t_a = (a - from).dot(direction) / length_sq;
  const double t_b = (b - from).dot(direction) / length_sq;
  const double low = std::max(0.0, std::min(t_a, t_b));
  const double high = std::min(1.0, std::max(t_a, t_b));
  if (low >= high) return {primitive};
  const double tolerance = kInsideTolerance / std::sqrt(length_sq);
  std::vector<PathPrimitive> pieces;
  if (low > tolerance) pieces.push_back(PathPrimitive::segment(from, from + low * direction));
  if (high < 1.0 - tolerance) {
    pieces.push_back(PathPrimitive::segment(from + high * direction, primitive.end()));
  }
  return pieces;
}

/// The legs of `waypoints` that are the shortest way into the offset free area from a
/// start nearer than `wall_distance` to a wall, and out of it to such a goal: pairs of
/// their ends.
std::vector<std::pair<Point2, Point2>> wallBandLegs(const std::vector<Pose2>& waypoints,
                                                    const PolygonWithHoles& free_area,
                                                    double wall_distance) {
  std::vector<std::pair<Point2, Point2>> legs;
  if (waypoints.size() < 2 || !(wall_distance > 0.0)) return legs;
  const auto in_band = [&](const Point2& p) {
    return !keepsClearance(distanceToBoundary(p, free_area), wall_distance);
  };
  const Point2 first = waypoints.front().position();
  const Point2 last = waypoints.back().position();
  if (in_band(first)) legs.emplace_back(first, waypoints[1].position());
  if (in_band(last)) legs.emplace_back(waypoints[waypoints.size() - 2].position(), last);
  return legs;
}

}  // namespace

SmoothedPath TrajectoryGenerator::smoothedPath(const std::vector<Pose2>& waypoints,
                                               const PolygonWithHoles& free_area) const {
  if (options_.strategy == SmoothingStrategy::kCoverageSafe) {
    // The global programme keeping the sharp path's coverage; Algorithm 1's result, which
    // may lose coverage, is no alternative.
    return GlobalPathSmoother(free_area, options_.global).smooth(waypoints);
  }
  SmoothedPath local =
      PathSmoother(free_area, options_.vehicle().turning_radius, options_.global.clearance)
          .smooth(waypoints);
  if (options_.strategy == SmoothingStrategy::kLocal) return local;
  SmoothedPath global = GlobalPathSmoother(free_area, options_.global).smooth(waypoints);
  if (options_.global.preserved_sensor) return global;
  // The global programme's cost is exact except where a leg piece is too short for the
  // speed change between its neighbours; the exact times settle those few cases, so that
  // the global strategy is never slower than Algorithm 1.
  const TrajectoryTiming timing(options_.vehicle());
  return timing.traversalTime(global.primitives) <= timing.traversalTime(local.primitives) ? global
                                                                                           : local;
}

ContinuousCurvaturePath TrajectoryGenerator::continuousCurvature(
    const std::vector<PathPrimitive>& path, const std::vector<Pose2>& waypoints,
    const PolygonWithHoles& free_area) const {
  const ContinuousCurvatureTurns turns(free_area, options_.curvature_rate_max);
  // The strategies that keep coverage keep it through the turns too, with their sensor.
  const GlobalSmoothingOptions& global = options_.global;
  const std::optional<FrustumSensor>& sensor =
      options_.strategy == SmoothingStrategy::kLocal
          ? std::nullopt
          : (global.safe_sensor ? global.safe_sensor : global.preserved_sensor);
  if (!sensor) return turns.apply(path, nullptr);
  std::vector<Point2> points;
  points.reserve(waypoints.size());
  for (const Pose2& waypoint : waypoints) points.push_back(waypoint.position());
  PathCoverageCheck check(free_area, global.wall_distance, global.exact_offset_parts, *sensor,
                          cornerWaypoints(points));
  return turns.apply(path, &check);
}

GeneratedTrajectory TrajectoryGenerator::generate(const std::vector<Pose2>& waypoints,
                                                  const PolygonWithHoles& free_area) const {
  if (waypoints.empty()) {
    throw InvalidInputError("no waypoints: a trajectory needs at least one");
  }
  GeneratedTrajectory trajectory;
  if (options_.smoothing) {
    SmoothedPath smoothed = smoothedPath(waypoints, free_area);
    trajectory.path = std::move(smoothed.primitives);
    trajectory.statistics = smoothed.statistics;
    if (options_.turn_curve == TurnCurve::kClothoid) {
      ContinuousCurvaturePath continuous =
          continuousCurvature(trajectory.path, waypoints, free_area);
      trajectory.path = std::move(continuous.primitives);
      trajectory.statistics.clothoid = continuous.turns_clothoid;
    }
  } else {
    trajectory.path = SegmentPathBuilder().build(waypoints);
    trajectory.statistics = segmentPathStatistics(trajectory.path);
  }
  if (trajectory.path.empty()) {
    // Every waypoint at one place: the robot stays there, turned as the first waypoint.
    const Pose2& only = waypoints.front();
    trajectory.path.push_back(PathPrimitive::rotation(
        only.position(), std::isfinite(only.yaw) ? wrapAngle(only.yaw) : 0.0, 0.0));
  }
  TrajectorySampler(options_.segment_sampling_distance, options_.arc_sampling_distance,
                    options_.rotation_sampling_angle)
      .sample(trajectory.path, trajectory.poses);
  trajectory.traversal_time_s =
      TrajectoryTiming(options_.vehicle()).assignTimes(trajectory.path, trajectory.poses);
  trajectory.trajectory_length_m = primitivePathLength(trajectory.path);
  trajectory.max_curvature = primitivePathMaxCurvature(trajectory.path);

  const std::vector<std::pair<Point2, Point2>> excepted =
      wallBandLegs(waypoints, free_area, options_.wall_distance);
  std::vector<PathPrimitive> measured = trajectory.path;
  for (const auto& [a, b] : excepted) {
    std::vector<PathPrimitive> off;
    for (const PathPrimitive& primitive : measured) {
      for (PathPrimitive& piece : offLeg(primitive, a, b)) off.push_back(std::move(piece));
    }
    measured = std::move(off);
  }
  std::vector<PathPrimitive> inside;
  for (const PathPrimitive& primitive : measured) {
    if (contains(free_area, primitive.start(), kInsideTolerance) &&
        contains(free_area, primitive.end(), kInsideTolerance)) {
      inside.push_back(primitive);
    }
  }
  const ClosestApproach approach = primitivePathClosestApproach(inside, free_area);
  trajectory.min_obstacle_clearance_m = approach.distance_m;
  trajectory.closest_approach = approach.point;
  return trajectory;
}

}  // namespace kinematic_coverage::core
