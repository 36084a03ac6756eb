#include "trajectory_generation_tools/smoothing/path_smoother.h"

#include <cmath>
#include <string>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "trajectory_generation_tools/smoothing/corner_smoother.h"
#include "trajectory_generation_tools/smoothing/smoothed_path_assembler.h"

namespace kinematic_coverage::core {

PathSmoother::PathSmoother(const PolygonWithHoles& free_area, double turning_radius,
                           double clearance)
    : index_(free_area, clearance), radius_(turning_radius) {
  if (!std::isfinite(turning_radius) || turning_radius <= 0.0) {
    throw InvalidInputError("the turning radius must be a positive finite number, got " +
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
  std::vector<std::optional<CornerSmoothing>> smoothings;
  if (points.size() >= 3) smoothings.reserve(points.size() - 2);
  const CornerSmoother smoother(index_);
  Point2 current = points.empty() ? Point2::Zero() : points.front();  // end of the path so far
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    const Point2 incoming = (points[i] - points[i - 1]).normalized();
    smoothings.push_back(smoother.smooth({current, points[i], points[i + 1], radius_, incoming}));
    current = smoothings.back() ? smoothings.back()->arcs.back().end() : points[i];
  }
  return SmoothedPathAssembler::assemble(points, smoothings);
}

}  // namespace kinematic_coverage::core
