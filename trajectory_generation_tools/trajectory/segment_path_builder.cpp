#include "trajectory_generation_tools/trajectory/segment_path_builder.h"

#include <cmath>
#include <string>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "trajectory_generation_tools/trajectory/primitive_path_validation.h"

namespace kinematic_coverage::core {

std::vector<PathPrimitive> SegmentPathBuilder::build(const std::vector<Pose2>& waypoints) const {
  std::vector<Pose2> distinct;
  distinct.reserve(waypoints.size());
  for (std::size_t i = 0; i < waypoints.size(); ++i) {
    const Pose2& waypoint = waypoints[i];
    if (!std::isfinite(waypoint.x) || !std::isfinite(waypoint.y)) {
      throw InvalidInputError("waypoint " + std::to_string(i) + " has a non-finite coordinate");
    }
    if (distinct.empty() ||
        (waypoint.position() - distinct.back().position()).norm() > kDegenerateLength) {
      distinct.push_back(waypoint);
    }
  }

  std::vector<PathPrimitive> path;
  if (distinct.empty()) return path;
  if (distinct.size() == 1) {
    const double yaw = std::isfinite(distinct.front().yaw) ? wrapAngle(distinct.front().yaw) : 0.0;
    path.push_back(PathPrimitive::rotation(distinct.front().position(), yaw, 0.0));
    return path;
  }

  path.reserve(2 * distinct.size());
  double previous_heading = 0.0;
  for (std::size_t i = 0; i + 1 < distinct.size(); ++i) {
    const Point2 from = distinct[i].position();
    const Point2 to = distinct[i + 1].position();
    const double heading = headingOf(from, to);
    if (i > 0) {
      const double turn = wrapAngle(heading - previous_heading);
      if (std::abs(turn) > kCollinearTolerance) {
        path.push_back(PathPrimitive::rotation(from, previous_heading, turn));
      }
    }
    path.push_back(PathPrimitive::segment(from, to));
    previous_heading = heading;
  }
  return path;
}

std::vector<PathPrimitive> SegmentPathBuilder::build(const std::vector<Point2>& waypoints) const {
  std::vector<Pose2> poses;
  poses.reserve(waypoints.size());
  for (const Point2& p : waypoints) poses.push_back({p.x(), p.y(), 0.0});
  return build(poses);
}

}  // namespace kinematic_coverage::core
