#include "trajectory_generation_tools/smoothing/corner_waypoints.h"

#include <cmath>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "trajectory_generation_tools/smoothing/corner_geometry.h"

namespace kinematic_coverage::core {

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

}  // namespace kinematic_coverage::core
