#pragma once

#include <cmath>
#include <limits>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/simulation/robot_simulator.h"

namespace kinematic_coverage::core {

/// How near a simulated robot's true path came to the walls and obstacles: what a run in
/// a current or with a navigation error means for the vehicle's safety, which the tracking
/// error alone does not say.
struct DrivenPathClearance {
  /// m: over the recorded poses inside the free area, the smallest distance to the hull
  /// and the holes; 0 after a contact; infinity when no pose lies inside.
  double min_clearance_m = std::numeric_limits<double>::infinity();
  /// s: time spent inside an obstacle (a hole of the free area).
  double obstacle_time_s = 0.0;
  /// s: time spent outside the hull after the robot was first inside the free area (a
  /// start outside the hull, from a boat, is not counted).
  double outside_hull_time_s = 0.0;
  /// The first pose inside an obstacle or outside the hull after being inside: t is NaN
  /// when there was none.
  double first_contact_t = std::numeric_limits<double>::quiet_NaN();
  Point2 first_contact = Point2::Zero();

  /// True when the robot drove into an obstacle or out through the hull.
  bool contact() const { return !std::isnan(first_contact_t); }
};

/// Measures the clearance of the poses of `steps` (one every `sim_dt` s) from the hull
/// and holes of `free_area`.
DrivenPathClearance measureDrivenPathClearance(const std::vector<SimulationStep>& steps,
                                               const PolygonWithHoles& free_area, double sim_dt);

}  // namespace kinematic_coverage::core
