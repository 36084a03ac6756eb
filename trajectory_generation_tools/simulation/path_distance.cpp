#include "trajectory_generation_tools/simulation/path_distance.h"

#include <cmath>
#include <string>
#include <utility>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// The polyline's segments between distinct consecutive points (one point: a segment of
/// that point), checked finite.
std::pair<std::vector<Point2>, std::vector<Point2>> segmentsOf(const std::vector<Point2>& points) {
  if (points.empty()) throw InvalidInputError("path distance: the path has no points");
  std::pair<std::vector<Point2>, std::vector<Point2>> segments;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!std::isfinite(points[i].x()) || !std::isfinite(points[i].y())) {
      throw InvalidInputError("path distance: point " + std::to_string(i) + " is not finite");
    }
    if (i > 0 && points[i] != points[i - 1]) {
      segments.first.push_back(points[i - 1]);
      segments.second.push_back(points[i]);
    }
  }
  if (segments.first.empty()) {
    segments.first.push_back(points.front());
    segments.second.push_back(points.front());
  }
  return segments;
}

NearestSegmentIndex indexOf(const std::vector<Point2>& points) {
  auto [starts, ends] = segmentsOf(points);
  return NearestSegmentIndex(std::move(starts), std::move(ends));
}

}  // namespace

PathDistance::PathDistance(const std::vector<Point2>& points) : segments_(indexOf(points)) {}

double PathDistance::distance(const Point2& point) const {
  return segments_.nearest(point).distance;
}

Point2 PathDistance::nearestPoint(const Point2& point) const {
  const std::uint32_t s = segments_.nearest(point).segment;
  return closestPointOnSegment(point, segments_.start(s), segments_.end(s));
}

}  // namespace kinematic_coverage::core
