#include "trajectory_generation_tools/simulation/driven_path_clearance.h"

#include <algorithm>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {

DrivenPathClearance measureDrivenPathClearance(const std::vector<SimulationStep>& steps,
                                               const PolygonWithHoles& free_area, double sim_dt) {
  DrivenPathClearance clearance;
  bool entered = false;
  for (const SimulationStep& step : steps) {
    const Point2 position = step.pose.position();
    const bool inside_hull = insideRing(position, free_area.hull);
    const bool in_obstacle =
        inside_hull && std::any_of(free_area.holes.begin(), free_area.holes.end(),
                                   [&](const Ring& hole) { return insideRing(position, hole); });
    bool touches = in_obstacle;
    if (in_obstacle) clearance.obstacle_time_s += sim_dt;
    if (inside_hull && !in_obstacle) {
      entered = true;
      clearance.min_clearance_m =
          std::min(clearance.min_clearance_m, distanceToBoundary(position, free_area));
    } else if (!inside_hull && entered) {
      clearance.outside_hull_time_s += sim_dt;
      touches = true;
    }
    if (touches && !clearance.contact()) {
      clearance.first_contact_t = step.t;
      clearance.first_contact = position;
    }
  }
  if (clearance.contact()) clearance.min_clearance_m = 0.0;
  return clearance;
}

}  // namespace kinematic_coverage::core
