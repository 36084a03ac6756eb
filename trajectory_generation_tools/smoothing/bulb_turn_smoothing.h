#pragma once

#include <optional>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/smoothing/corner_smoothing.h"

namespace kinematic_coverage::core {

/// Two consecutive corners that turn the same way (the end of a sweep: up a lane, along
/// the boundary, down the next lane), taken by a turn that stays on the near side of the
/// middle leg and runs along it: a first arc turning away from the corners, an arc turning
/// with them onto the middle leg's line, a straight run along that line, an arc turning off
/// it, and a last arc turning away again onto the outgoing leg. Where lanes are closer
/// than two turning radii this is the bulb (or keyhole) turn of agricultural coverage
/// planning. Beyond the thesis (the global strategy): inner smoothing cuts both corners
/// and with them the strip beyond the lanes' ends that only the sharp path's footprint
/// sees; a turn that drives along the middle leg sees that strip as the sharp path does.
class BulbTurnSmoothing {
 public:
  /// The bulb turn from the leg [a, b1] to the leg [b2, c] with arcs of `radius`, whose
  /// run along the line of [b1, b2] goes from `run_from` to `run_to` (fractions of the
  /// middle leg, 0 at b1, run_from <= run_to; equal: the turn touches the line at one
  /// point). entry_distance is measured back from b1 along [b1, a], exit_distance from b2
  /// along [b2, c], and `corners` is 2. nullopt when the corners do not turn the same
  /// way, the arcs cannot be tangent to each other (the run starts too far along the
  /// middle leg for the incoming lane, or ends too early for the outgoing one), an arc
  /// away from the corners would sweep pi or more, or the turn would turn more than the
  /// two corners do.
  static std::optional<CornerSmoothing> compute(const Point2& a, const Point2& b1, const Point2& b2,
                                                const Point2& c, double radius, double run_from,
                                                double run_to);
};

}  // namespace kinematic_coverage::core
