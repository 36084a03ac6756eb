#pragma once

#include <cstdint>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/path/path_primitive.h"

namespace kinematic_coverage::core {

/// One sampled pose of a trajectory (a row of `trajectory.csv`), with
/// where on the primitive path it lies so that timing can date it.
struct TrajectoryPose {
  double t = 0.0;    ///< seconds from the start
  double x = 0.0;    ///< metres
  double y = 0.0;    ///< metres
  double yaw = 0.0;  ///< heading of travel, radians in (-pi, pi]
  /// The kind of the primitive that leads to this pose (the first pose: of the primitive
  /// it starts), so the motion from the previous pose to this one is of this kind.
  PrimitiveKind kind = PrimitiveKind::kSegment;
  /// Index of that primitive in the path (32 bits keep a pose at 48 bytes: a long
  /// trajectory has millions of poses).
  std::uint32_t primitive = 0;
  double fraction = 0.0;  ///< of that primitive's length (a rotation: of its turn)

  Point2 position() const { return {x, y}; }
  Pose2 pose() const { return {x, y, yaw}; }
};

}  // namespace kinematic_coverage::core
