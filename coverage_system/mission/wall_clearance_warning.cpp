#include "coverage_system/mission/wall_clearance_warning.h"

#include <cmath>
#include <sstream>

#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {

std::optional<std::string> wallClearanceWarning(double min_obstacle_clearance_m,
                                                const PlannerParameters& parameters) {
  const double smoothing_clearance = smoothingClearanceOf(parameters);
  const double gap_clearance = gapClearanceOf(parameters);
  const double wall_distance = parameters.wall_distance;
  if (!std::isfinite(min_obstacle_clearance_m) ||
      keepsClearance(min_obstacle_clearance_m, wall_distance)) {
    return std::nullopt;
  }
  std::ostringstream out;
  out.precision(4);
  out << "the trajectory passes " << min_obstacle_clearance_m
      << " m from a wall or obstacle, nearer than wall_distance " << wall_distance << " m";
  const bool smoothing_allows =
      parameters.smoothing && !keepsClearance(smoothing_clearance, wall_distance);
  const bool gaps_allow = !keepsClearance(gap_clearance, wall_distance);
  if (smoothing_allows) {
    out << ": smoothing_clearance " << smoothing_clearance
        << " m lets its turns into the wall band (smoothing_clearance: wall_distance keeps them "
           "out)";
  }
  if (gaps_allow) {
    out << (smoothing_allows ? "; " : ": ") << "gap_clearance " << gap_clearance
        << " m lets its transits through narrower gaps (gap_clearance: wall_distance keeps them "
           "out)";
  }
  if (!smoothing_allows && !gaps_allow) {
    out << ": its waypoints come that near (a waypoint list drawn into the wall band, or "
           "gaps the planner was allowed through)";
  }
  return out.str();
}

}  // namespace kinematic_coverage::core
