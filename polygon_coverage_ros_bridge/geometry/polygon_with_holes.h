#pragma once

#include <Eigen/Core>
#include <vector>

namespace kinematic_coverage::core {

/// A point in the plane, metres.
using Point2 = Eigen::Vector2d;

/// A closed ring of vertices; the closing edge back to the first vertex is implied.
using Ring = std::vector<Point2>;

/// An area: the hull minus the holes. After cleaning, the hull is counter-clockwise,
/// the holes are clockwise, and no two rings cross.
struct PolygonWithHoles {
  Ring hull;
  std::vector<Ring> holes;
};

/// A planar pose: position and heading (yaw about z, radians in (-pi, pi]).
struct Pose2 {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;
  Point2 position() const { return {x, y}; }
};

}  // namespace kinematic_coverage::core
