#pragma once

#include "trajectory_generation_tools/smoothing/boundary_edge_index.h"
#include "trajectory_generation_tools/smoothing/corner.h"
#include "trajectory_generation_tools/smoothing/corner_smoothing.h"

namespace kinematic_coverage::core {

/// The feasibility test of Algorithm 1 (thesis 3.2): continuity and freedom from collision.
class SmoothingFeasibility {
 public:
  /// Checks against the edges in `index`, which must outlive this object.
  explicit SmoothingFeasibility(const BoundaryEdgeIndex& index) : index_(index) {}

  /// True when `smoothing` of `corner` is feasible:
  /// - continuity: the first tangent point lies on [A, B], so the smoothing starts no sooner
  ///   than the previous one ended (A is that end), and the last on [B, C] (both within
  ///   kLegTolerance times the corner's scale);
  /// - no collision: the joining segments [A, I1] and [I_last, C] and every arc keep more
  ///   than kContactTolerance from the hull and holes, and A lies in the free area (so the
  ///   connected primitives do too).
  bool feasible(const Corner& corner, const CornerSmoothing& smoothing) const;

 private:
  const BoundaryEdgeIndex& index_;
};

}  // namespace kinematic_coverage::core
