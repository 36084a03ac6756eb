#pragma once

#include <optional>

#include "trajectory_generation_tools/smoothing/corner.h"
#include "trajectory_generation_tools/smoothing/corner_smoothing.h"

namespace kinematic_coverage::core {

/// Outer smoothing with the minimum at the tangent intersection boundary (thesis 3.2.2,
/// Alg. 6 to 8, Eq. 3.5 to 3.7), for legs too short for the bisector variant: the outer
/// circle of the shorter leg touches it at its far end (A or C), the other outer circle is
/// its mirror image, and the middle circle touches both on the bisector.
class OuterSmoothingTangent {
 public:
  /// The three arcs, or nullopt when the corner is straight or degenerate or the outer
  /// circles violate 4r > |O1O3| > 2r (Alg. 8). Legs and collisions: SmoothingFeasibility.
  static std::optional<CornerSmoothing> compute(const Corner& corner);
};

}  // namespace kinematic_coverage::core
