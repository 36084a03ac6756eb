#pragma once

#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/path/path_primitive.h"

namespace kinematic_coverage::core {

/// Builds the path of `smoothing: false` (docs/REFERENCE.md, Parameters) from a waypoint path:
/// straight segments joined by in-place rotations wherever the heading changes, so a
/// robot drives each leg and turns on the spot at the waypoint.
class SegmentPathBuilder {
 public:
  /// Headings of consecutive legs closer than this (radians) are collinear: no rotation.
  static constexpr double kCollinearTolerance = 1e-9;

  /// The path through `waypoints`. Consecutive waypoints within kDegenerateLength of each
  /// other are one waypoint. Each remaining interior waypoint where the heading changes
  /// gets a rotation by the wrapped heading change (the shorter way; a full reversal
  /// turns +pi, counter-clockwise). No rotation before the first leg or after the last.
  /// One distinct waypoint gives a single zero-turn rotation at it (keeping its yaw), so
  /// the trajectory still has its pose; no waypoints give an empty path.
  /// Throws InvalidInputError for a non-finite coordinate.
  std::vector<PathPrimitive> build(const std::vector<Pose2>& waypoints) const;

  /// As above for bare points (a lone waypoint gets yaw 0).
  std::vector<PathPrimitive> build(const std::vector<Point2>& waypoints) const;
};

}  // namespace kinematic_coverage::core
