#pragma once

#include <cmath>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {
namespace testing {

/// A square of side `side` centred on `centre`, turned by `angle`, counter-clockwise.
inline Ring turnedSquare(const Point2& centre, double side, double angle) {
  const Point2 u(std::cos(angle), std::sin(angle));
  const Point2 v(-u.y(), u.x());
  const double h = 0.5 * side;
  return {centre - h * u - h * v, centre + h * u - h * v, centre + h * u + h * v,
          centre - h * u + h * v};
}

}  // namespace testing
}  // namespace kinematic_coverage::core
