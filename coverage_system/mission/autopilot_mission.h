#pragma once

#include <limits>
#include <vector>

#include "polygon_coverage_ros_bridge/base/vehicle_limits.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/path/path_primitive.h"

namespace kinematic_coverage::core {

/// A waypoint of a vehicle's autopilot mission, in the mission's local frame.
struct AutopilotWaypoint {
  Point2 position = Point2::Zero();
  double speed = 0.0;  ///< m/s on the way to it (the first: the speed of the first leg)
  /// The autopilot must reach it, not cut it: a sharp corner (the trajectory turns on the
  /// spot there), or a waypoint whose cut would come nearer the walls than the path.
  bool hold = false;
};

/// What an autopilot drives of a trajectory: its waypoints, with the closest approach to
/// the walls of the path it drives when it cuts every waypoint but the held ones by the
/// corner-cutting radius.
struct AutopilotMission {
  std::vector<AutopilotWaypoint> waypoints;
  /// m: the least distance from the hull and holes of the cut path (infinity without walls
  /// or waypoints); `closest_cut` is where.
  double corner_cut_clearance_m = std::numeric_limits<double>::infinity();
  Point2 closest_cut = Point2::Zero();
};

/// Turns a smoothed trajectory into the waypoints of an autopilot mission (ArduSub, PX4),
/// which drives straight from waypoint to waypoint: a segment's end is a waypoint, an arc or
/// a clothoid becomes the polygon of its tangents at poses at most kMaxTurnStep of heading
/// apart (its corners the waypoints: on the curve's outer side, so that the straight legs
/// between them never come nearer the walls on its inner side than the curve does), and an
/// in-place rotation (a sharp corner) adds none, so that a sharp corner stays one waypoint. Each
/// waypoint carries the speed of the piece that leads to it: v_max on segments, the arc speed
/// min(v_max, yaw_rate_max / curvature) on curves. Autopilots turn for the next waypoint
/// once within their waypoint radius (ArduSub: WPNAV_RADIUS) of the current one: the path
/// then cut lies, near each waypoint, within the convex hull of the stretch from the
/// corner-cutting radius before it to that radius after it, so the cut path's clearance is
/// measured on the chords of those stretches and on the waypoint path itself. A waypoint
/// whose chord comes nearer the walls than the wall distance (or the waypoint path, where
/// that is nearer) is held: the autopilot stops there instead of cutting it.
class AutopilotMissionBuilder {
 public:
  /// The largest heading change between a curve's waypoints, rad.
  static constexpr double kMaxTurnStep = M_PI / 8.0;

  /// `corner_cutting_radius` (m, >= 0): how far before a waypoint the autopilot turns.
  AutopilotMissionBuilder(const VehicleLimits& vehicle, double corner_cutting_radius)
      : vehicle_(vehicle), corner_cutting_radius_(corner_cutting_radius) {}

  /// The mission of `path` (a GeneratedTrajectory's primitives), its cut path measured
  /// against the hull and holes of `free_area`, but for the first and last legs where they
  /// join a start or goal nearer than `wall_distance` to a wall (as the trajectory's
  /// min_obstacle_clearance_m leaves them out).
  AutopilotMission build(const std::vector<PathPrimitive>& path, const PolygonWithHoles& free_area,
                         double wall_distance) const;

 private:
  /// The speed on `primitive`, m/s.
  double speedOn(const PathPrimitive& primitive) const;

  VehicleLimits vehicle_;
  double corner_cutting_radius_;
};

}  // namespace kinematic_coverage::core
