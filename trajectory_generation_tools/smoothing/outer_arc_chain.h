#pragma once

#include <optional>

#include "trajectory_generation_tools/smoothing/corner_geometry.h"
#include "trajectory_generation_tools/smoothing/corner_smoothing.h"

namespace kinematic_coverage::core {

/// The three tangent arcs of an outer smoothing ("further arc generation similarly to
/// Alg. 5", Alg. 5 and 8) from the circle centres O1, O2, O3 of radius r.
class OuterArcChain {
 public:
  /// Arcs I1 -> I12 about O1, I12 -> I23 about O2, I23 -> I3 about O3, where I1 and I3 are
  /// the projections of O1 and O3 onto the legs and I12, I23 the circles' touching points.
  /// O2 turns the way the path turns, O1 and O3 the other way (Alg. 5). O3 must be the
  /// mirror image of O1 across the bisector and O2 lie on it, so the first and last arcs
  /// sweep the same angle. nullopt when a sweep is not finite.
  static std::optional<CornerSmoothing> build(const CornerGeometry& geometry, const Point2& o1,
                                              const Point2& o2, const Point2& o3,
                                              SmoothingVariant variant);
};

}  // namespace kinematic_coverage::core
