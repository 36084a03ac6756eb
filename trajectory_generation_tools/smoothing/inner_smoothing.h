#pragma once

#include <optional>

#include "trajectory_generation_tools/smoothing/corner.h"
#include "trajectory_generation_tools/smoothing/corner_smoothing.h"

namespace kinematic_coverage::core {

/// Inner smoothing (thesis 3.2.1, Alg. 2 and 3, Eq. 3.1 and 3.2): one arc of the circle of
/// radius r inscribed in the angle ABC, segment-arc-segment.
class InnerSmoothing {
 public:
  /// The arc, or nullopt when the corner is straight, a reversal or degenerate. Whether the
  /// tangent points lie on the legs and the arc is free is SmoothingFeasibility's question.
  static std::optional<CornerSmoothing> compute(const Corner& corner);
};

}  // namespace kinematic_coverage::core
