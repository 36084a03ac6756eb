#include "trajectory_generation_tools/smoothing/corner_smoother.h"

#include "trajectory_generation_tools/smoothing/inner_smoothing.h"
#include "trajectory_generation_tools/smoothing/outer_smoothing_bisector.h"
#include "trajectory_generation_tools/smoothing/outer_smoothing_tangent.h"

namespace kinematic_coverage::core {

std::optional<CornerSmoothing> CornerSmoother::smooth(const Corner& corner) const {
  using Variant = std::optional<CornerSmoothing> (*)(const Corner&);
  // Alg. 1's order.
  for (const Variant variant : {&InnerSmoothing::compute, &OuterSmoothingBisector::compute,
                                &OuterSmoothingTangent::compute}) {
    std::optional<CornerSmoothing> smoothing = variant(corner);
    if (smoothing && feasibility_.feasible(corner, *smoothing)) return smoothing;
  }
  return std::nullopt;
}

}  // namespace kinematic_coverage::core
