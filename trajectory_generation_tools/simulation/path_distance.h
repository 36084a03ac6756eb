#pragma once

#include <vector>

#include "polygon_coverage_ros_bridge/geometry/nearest_segment_index.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// The distance from a point to a polyline, for the tracking error of a simulated robot:
/// the distance from the robot to the nearest point of the desired path (docs/REFERENCE.md,
/// Metrics: `tracking_error_sum_m`). The polyline's segments are bucketed in a uniform
/// grid, so that a query near the path looks at a few segments however long the path is.
class PathDistance {
 public:
  /// Indexes the polyline through `points` (consecutive equal points allowed; one point is
  /// a path of that point). Throws InvalidInputError for no points or a non-finite one.
  explicit PathDistance(const std::vector<Point2>& points);

  /// The distance from `point` to the nearest point of the polyline (exact, for any point,
  /// near the path or far from it).
  double distance(const Point2& point) const;

  /// The nearest point of the polyline to `point` (the first along it among equally near
  /// ones).
  Point2 nearestPoint(const Point2& point) const;

 private:
  NearestSegmentIndex segments_;
};

}  // namespace kinematic_coverage::core
