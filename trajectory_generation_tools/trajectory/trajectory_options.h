#pragma once

#include "polygon_coverage_ros_bridge/base/vehicle_limits.h"
#include "trajectory_generation_tools/smoothing/global_smoothing_options.h"
#include "trajectory_generation_tools/smoothing/smoothing_strategy.h"

namespace kinematic_coverage::core {

/// The curve a smoothed turn between two straight legs takes (parameter `turn_curve`).
enum class TurnCurve {
  kArc,       ///< the thesis's circular arc (Dubins-like): a curvature jump at each end
  kClothoid,  ///< clothoid-arc-clothoid, continuous in curvature (ContinuousCurvatureTurns)
};

/// The options trajectory generation reads (docs/REFERENCE.md, Parameters): how the
/// waypoint path is smoothed, how densely the trajectory is sampled, and the robot whose
/// velocity model dates it.
struct TrajectoryOptions {
  bool smoothing = true;  ///< false: segments and in-place rotations
  SmoothingStrategy strategy = SmoothingStrategy::kCoverageSafe;
  /// The smoothing options (preserved_sensor set: the global strategy smooths only where
  /// nothing goes unseen, `coverage_preserving`) and the one robot of every strategy and
  /// of the timing, `global.vehicle`.
  GlobalSmoothingOptions global;
  double segment_sampling_distance = 0.5;  ///< m
  double arc_sampling_distance = 0.1;      ///< m
  double rotation_sampling_angle = 0.2;    ///< rad
  TurnCurve turn_curve = TurnCurve::kArc;
  double curvature_rate_max = 2.0;  ///< 1/m^2: the clothoids' curvature change per metre
  /// m: the distance the planner keeps from the hull and holes (wall_distance). The legs
  /// that join a start or goal nearer than this to the offset free area are left out of
  /// min_obstacle_clearance_m (docs/REFERENCE.md, Collisions and clearance).
  double wall_distance = 0.0;

  /// The velocity model; its turning_radius is Algorithm 1's radius.
  const VehicleLimits& vehicle() const { return global.vehicle; }
};

}  // namespace kinematic_coverage::core
