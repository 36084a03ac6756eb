#include "trajectory_generation_tools/smoothing/smoothing_feasibility.h"

#include <cmath>

#include "trajectory_generation_tools/smoothing/corner_geometry.h"

namespace kinematic_coverage::core {

bool SmoothingFeasibility::feasible(const Corner& corner, const CornerSmoothing& smoothing) const {
  const std::optional<CornerGeometry> geometry = CornerGeometry::of(corner);
  if (!geometry || smoothing.arcs.empty()) return false;
  const CornerGeometry& g = *geometry;
  const double tolerance = kLegTolerance * g.scale();
  const double entry = smoothing.entry_distance;
  const double exit = smoothing.exit_distance;
  if (!std::isfinite(entry) || !std::isfinite(exit)) return false;
  if (entry < -tolerance || entry > g.lengthBA() + tolerance) return false;
  if (exit < -tolerance || exit > g.lengthBC() + tolerance) return false;

  const Point2 entry_point = g.b() + entry * g.towardA();
  const Point2 exit_point = g.b() + exit * g.towardC();
  if (!index_.segmentClear(corner.a, entry_point)) return false;
  if (!index_.segmentClear(exit_point, corner.c)) return false;
  for (const PathPrimitive& arc : smoothing.arcs) {
    if (!std::isfinite(arc.sweep()) || !arc.start().allFinite() || !arc.end().allFinite() ||
        !index_.arcClear(arc)) {
      return false;
    }
  }
  return index_.inside(corner.a);
}

}  // namespace kinematic_coverage::core
