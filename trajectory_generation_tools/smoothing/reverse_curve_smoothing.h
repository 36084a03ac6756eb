#pragma once

#include <optional>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/smoothing/corner_smoothing.h"

namespace kinematic_coverage::core {

/// Two consecutive corners that turn opposite ways, smoothed together by two tangent arcs
/// of one radius (a reverse curve, or S-curve): the first tangent to the incoming leg and
/// turning like the first corner, the second tangent to the outgoing leg and turning like
/// the second. Beyond the thesis (the global strategy): it takes the lane-change jogs whose middle
/// leg is too short for two inner smoothings, where Algorithm 1 falls back to a slow
/// outer loop or a sharp turn.
class ReverseCurveSmoothing {
 public:
  /// Middle legs longer than this many radii get no reverse curve (two inner smoothings
  /// fit there).
  static constexpr double kMaxMiddleLegRadii = 4.0;
  /// Corners turning by more than 90 degrees plus asin(this) get no reverse curve: their
  /// middle leg runs back along a neighbouring leg, and the curve would skip the
  /// excursion (the end of a sweep) that the sharp path drives to see.
  static constexpr double kMaxBackwardCosine = 0.1;

  /// The reverse curve from the leg [a, b1] to the leg [b2, c] with arcs of `radius`,
  /// whose inflection point (where the arcs touch) lies closest to the middle of
  /// [b1, b2]. entry_distance is |b1 I1| back along [b1, a], exit_distance |b2 I2| along
  /// [b2, c], and `corners` is 2. nullopt when the corners do not turn opposite ways, one
  /// turns by more than about 96 degrees (kMaxBackwardCosine), the middle leg is longer
  /// than kMaxMiddleLegRadii radii, or no curve starts on [a, b1] and
  /// ends beyond b2 with each arc sweeping less than pi.
  static std::optional<CornerSmoothing> compute(const Point2& a, const Point2& b1, const Point2& b2,
                                                const Point2& c, double radius);
};

}  // namespace kinematic_coverage::core
