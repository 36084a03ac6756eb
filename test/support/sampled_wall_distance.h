#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {
namespace testing {

/// The least distance from the walls of `free_area` to points of the polyline `path` a
/// centimetre apart: a test's own measure of the clearance that a path keeps.
inline double sampledWallDistance(const PolygonWithHoles& free_area,
                                  const std::vector<Point2>& path) {
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const Point2& a = path[i];
    const Point2& b = path[i + 1];
    const int steps = std::max(1, static_cast<int>(std::ceil((b - a).norm() / 0.01)));
    for (int k = 0; k <= steps; ++k) {
      least = std::min(least, distanceToBoundary(a + (b - a) * k / steps, free_area));
    }
  }
  return least;
}

}  // namespace testing
}  // namespace kinematic_coverage::core
