#pragma once

#include <optional>
#include <vector>

#include "trajectory_generation_tools/smoothing/corner_smoothing.h"
#include "trajectory_generation_tools/smoothing/path_smoother.h"

namespace kinematic_coverage::core {

/// Builds the primitive path that a smoothing strategy decided: joining segments along the
/// legs, each smoothed corner's arcs, and an in-place rotation at each corner left sharp.
/// Shared by Algorithm 1 (PathSmoother) and the global strategy (GlobalPathSmoother), so
/// that both produce paths of the same form and statistics counted the same way.
class SmoothedPathAssembler {
 public:
  /// The path through `corners` (cornerWaypoints output), where `smoothings[i]` is the
  /// smoothing of interior corner i + 1 or nullopt for a sharp turn (size: corners - 2;
  /// each smoothing must begin no sooner than the previous one ends). A smoothing of two
  /// corners (a reverse curve) at i also takes corner i + 2, whose entry is then ignored.
  static SmoothedPath assemble(const std::vector<Point2>& corners,
                               const std::vector<std::optional<CornerSmoothing>>& smoothings);
};

}  // namespace kinematic_coverage::core
