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

/// Two 10 m rooms joined by a strait 6 m long and exactly 2 m wide: with a 1 m wall
/// distance the mitred offset splits at the strait, which a robot keeping 1 m passes along
/// its middle.
inline PolygonWithHoles twoRoomsJoinedByATwoMetreStrait() {
  return {{{0, 0},
           {10, 0},
           {10, 4},
           {16, 4},
           {16, 0},
           {26, 0},
           {26, 10},
           {16, 10},
           {16, 6},
           {10, 6},
           {10, 10},
           {0, 10}},
          {}};
}

}  // namespace testing
}  // namespace kinematic_coverage::core
