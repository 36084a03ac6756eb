#pragma once

#include <vector>

#include "polygon_coverage_ros_bridge/base/trapezoidal_velocity_profile.h"
#include "polygon_coverage_ros_bridge/base/vehicle_limits.h"
#include "trajectory_generation_tools/path/path_primitive.h"
#include "trajectory_generation_tools/trajectory/trajectory_pose.h"

namespace kinematic_coverage::core {

/// How one primitive of a path is driven: when it starts, how long it takes, and its
/// speeds (m/s; all 0 for a rotation or a degenerate primitive).
struct PrimitiveTiming {
  double start_time_s = 0.0;
  double duration_s = 0.0;
  double entry_speed = 0.0;  ///< at its start
  double exit_speed = 0.0;   ///< at its end
  double peak_speed = 0.0;   ///< highest speed on it
  double speed_limit = 0.0;  ///< v_max on a segment, min(v_max, yaw_rate_max * r) on an arc
};

/// Dates a primitive path with the velocity model (v_max, a_max,
/// yaw_rate_max; Thesis section 3.3: "timestamps ... from the robot's velocity model").
///
/// Model: the speed along the path is the fastest profile with |acceleration| <= a_max
/// (a forward pass accelerating and a backward pass braking, on v^2 which is linear in
/// arc length at constant acceleration), under v <= v_max on segments and
/// v <= min(v_max, yaw_rate_max * r) on arcs, at rest at the start and the end. At a joint
/// of G1-continuous primitives (headings within kJoinHeadingTolerance) the robot keeps
/// going, no faster than both primitives allow. An in-place rotation is stop-rotate-go:
/// the robot brakes to rest, turns at the constant rate yaw_rate_max (angular
/// acceleration is not limited: the parameters give no limit, and this matches the
/// planner's per-segment cost), then accelerates from rest. A heading jump with no
/// rotation (a malformed path) forces a stop at the joint and takes no time to turn.
/// Degenerate primitives (isDegenerate) take no time. A single straight segment takes the
/// planner's rest-to-rest trapezoidal time: L / v + v / a when L >= v^2 / a, else
/// 2 sqrt(L / a).
class TrajectoryTiming {
 public:
  /// Throws InvalidInputError unless v_max, a_max and yaw_rate_max are positive and finite.
  explicit TrajectoryTiming(const VehicleLimits& limits);

  /// The limits v_max, a_max and yaw_rate_max.
  TrajectoryTiming(double v_max, double a_max, double yaw_rate_max);

  /// The timing of every primitive of `path`, in order. Throws InvalidInputError for a
  /// path validatePrimitivePath rejects.
  std::vector<PrimitiveTiming> profile(const std::vector<PathPrimitive>& path) const;

  /// The seconds from the start to `path` (0 for an empty path): `traversal_time_s`.
  double traversalTime(const std::vector<PathPrimitive>& path) const;

  /// Sets t of every pose sampled from `path` (TrajectorySampler) from its primitive and
  /// fraction, and returns the traversal time. t is non-decreasing along the poses and
  /// strictly increasing between poses at different positions. Throws InvalidInputError
  /// for a pose naming a primitive outside `path`.
  double assignTimes(const std::vector<PathPrimitive>& path,
                     std::vector<TrajectoryPose>& poses) const;

  /// Seconds from the start of `primitive` to `fraction` of it under `timing`.
  double timeWithin(const PathPrimitive& primitive, const PrimitiveTiming& timing,
                    double fraction) const;

 private:
  /// A primitive's motion in closed form: for a segment or arc, accelerate from `entry` to
  /// `peak` over [0, s1] (until t1), cruise to s2 (until t2), brake to `exit` at `length`;
  /// for a rotation, turn for `turn_duration`; a degenerate primitive takes no time.
  struct Phases {
    TrapezoidalVelocityProfile velocity{VehicleLimits{}};
    double length = 0.0;
    double entry = 0.0;
    double exit = 0.0;
    double peak = 0.0;
    double s1 = 0.0;
    double s2 = 0.0;
    double t1 = 0.0;
    double t2 = 0.0;
    double turn_duration = 0.0;
    /// Seconds from the primitive's start to `fraction` of it.
    double timeAt(double fraction) const;
  };
  Phases phasesOf(const PathPrimitive& primitive, const PrimitiveTiming& timing) const;

  VehicleLimits limits_;
};

}  // namespace kinematic_coverage::core
