#pragma once

#include <optional>

#include "trajectory_generation_tools/smoothing/boundary_edge_index.h"
#include "trajectory_generation_tools/smoothing/corner.h"
#include "trajectory_generation_tools/smoothing/corner_smoothing.h"
#include "trajectory_generation_tools/smoothing/smoothing_feasibility.h"

namespace kinematic_coverage::core {

/// Algorithm 1 for one corner: inner smoothing, then outer smoothing with the minimum at
/// the bisector boundary, then at the tangent intersection boundary; the first feasible
/// one wins.
class CornerSmoother {
 public:
  /// Collision checks against `index`, which must outlive this object.
  explicit CornerSmoother(const BoundaryEdgeIndex& index) : feasibility_(index) {}

  /// The first feasible smoothing of `corner` in Algorithm 1's order, or nullopt when none
  /// is (the corner stays sharp).
  std::optional<CornerSmoothing> smooth(const Corner& corner) const;

  /// Whether `smoothing` of `corner` passes Algorithm 1's feasibility test.
  bool feasible(const Corner& corner, const CornerSmoothing& smoothing) const {
    return feasibility_.feasible(corner, smoothing);
  }

 private:
  SmoothingFeasibility feasibility_;
};

}  // namespace kinematic_coverage::core
