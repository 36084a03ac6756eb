#pragma once

#include <optional>

#include "trajectory_generation_tools/smoothing/corner.h"
#include "trajectory_generation_tools/smoothing/corner_smoothing.h"

namespace kinematic_coverage::core {

/// Outer smoothing with the minimum at the bisector boundary (thesis 3.2.2, Alg. 4 and 5,
/// Eq. 3.3 and 3.4): three arcs, the middle circle's centre on the bisector at distance r
/// from B (so the path passes through B), the outer circles tangent to it and to the legs.
class OuterSmoothingBisector {
 public:
  /// The three arcs, or nullopt when the corner is straight or degenerate or the outer
  /// circles would overlap (|O1O3| < 2r). Legs and collisions: SmoothingFeasibility.
  static std::optional<CornerSmoothing> compute(const Corner& corner);
};

}  // namespace kinematic_coverage::core
