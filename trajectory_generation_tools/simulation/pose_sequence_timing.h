#pragma once

#include <vector>

#include "polygon_coverage_ros_bridge/base/trapezoidal_velocity_profile.h"
#include "polygon_coverage_ros_bridge/base/vehicle_limits.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// Times for a trajectory's poses where it carries none (the `trajectory` topic's
/// PoseArray, a pose file without a t column), so that the timed controller has a
/// reference: the planner's velocity model over the pose polyline. A piece between two
/// poses at one position is a rotation at yaw_rate_max from rest to rest; any other piece
/// is driven at most at min(v_max, yaw_rate_max / curvature), its curvature being its
/// heading change over its length, accelerating and braking at a_max (forward and backward
/// passes), and the robot stops before and after every rotation and at both ends.
class PoseSequenceTiming {
 public:
  explicit PoseSequenceTiming(const VehicleLimits& limits);

  /// Seconds from the first pose to each pose (non-decreasing; 0 for the first).
  std::vector<double> times(const std::vector<Pose2>& poses) const;

 private:
  VehicleLimits limits_;
  TrapezoidalVelocityProfile profile_;
};

}  // namespace kinematic_coverage::core
