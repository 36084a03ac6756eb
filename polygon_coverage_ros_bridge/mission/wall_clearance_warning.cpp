#include "polygon_coverage_ros_bridge/mission/wall_clearance_warning.h"

#include <cmath>
#include <sstream>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/parameters/stage_options.h"

namespace kinematic_coverage::core {

std::optional<std::string> wallClearanceWarning(double min_obstacle_clearance_m,
                                                const PlannerParameters& parameters) {
  const double allowed = smoothingClearanceOf(parameters);
  const double wall_distance = parameters.wall_distance;
  if (!parameters.smoothing || !std::isfinite(min_obstacle_clearance_m) ||
      keepsClearance(allowed, wall_distance) ||
      keepsClearance(min_obstacle_clearance_m, wall_distance)) {
    return std::nullopt;
  }
  std::ostringstream out;
  out.precision(4);
  out << "the trajectory passes " << min_obstacle_clearance_m
      << " m from a wall or obstacle, nearer than wall_distance " << wall_distance
      << " m: smoothing_clearance " << allowed
      << " m lets its turns into the wall band (smoothing_clearance: wall_distance keeps them "
         "out)";
  return out.str();
}

}  // namespace kinematic_coverage::core
