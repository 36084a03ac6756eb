#pragma once

#include <vector>

#include "trajectory_generation_tools/path/path_primitive.h"

namespace kinematic_coverage::core {

/// The arcs that replace one sharp corner (one arc for inner smoothing, three for the outer
/// smoothings), with where they leave the incoming leg and join the outgoing one.
struct CornerSmoothing {
  SmoothingVariant variant = SmoothingVariant::kNone;
  std::vector<PathPrimitive> arcs;  ///< consecutive, tangent arcs tagged with `variant`
  double entry_distance = 0.0;      ///< |B I1|: where the first arc leaves the leg [A, B]
  double exit_distance = 0.0;       ///< |B I_last|: where the last arc joins the leg [B, C]
  /// Corners replaced: 1, or 2 for a reverse curve, whose entry is measured from the first
  /// corner and exit from the second.
  int corners = 1;
};

}  // namespace kinematic_coverage::core
