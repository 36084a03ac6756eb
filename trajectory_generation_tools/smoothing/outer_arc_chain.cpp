#include "trajectory_generation_tools/smoothing/outer_arc_chain.h"

#include <cmath>

namespace kinematic_coverage::core {
namespace {

/// A first-arc sweep within this much (rad) below zero is rounding and snaps to zero.
constexpr double kSweepSnap = 1e-12;

}  // namespace

std::optional<CornerSmoothing> OuterArcChain::build(const CornerGeometry& g, const Point2& o1,
                                                    const Point2& o2, const Point2& o3,
                                                    SmoothingVariant variant) {
  const double r = g.radius();
  const double s = g.side();
  const double entry = g.alongBA(o1);
  const double exit = g.alongBC(o3);
  const Point2 i1 = g.b() + entry * g.towardA();
  const Point2 i12 = 0.5 * (o1 + o2);
  const Point2 i23 = 0.5 * (o2 + o3);

  // First arc: in the frame (radial at I1, direction of travel at I1) the touching point
  // I12 lies at the angle the arc sweeps (turning against the corner, Alg. 5's dir_1).
  const Point2 radial_x = (i1 - o1).normalized();
  const Point2 travel_y = -g.towardA();
  const Point2 to_o2 = o2 - o1;
  double first = std::atan2(to_o2.dot(travel_y), to_o2.dot(radial_x));
  if (first < 0.0) first = first > -kSweepSnap ? 0.0 : first + 2.0 * M_PI;
  // The headings add up: -first + middle - first = the corner's heading change, so the
  // middle arc (Alg. 5's dir_2, the corner's own direction) sweeps turn + 2 * first, and the
  // last arc sweeps as much as the first by the mirror symmetry across the bisector.
  const double middle = g.turn() + 2.0 * first;
  if (!std::isfinite(first) || !std::isfinite(middle)) return std::nullopt;

  CornerSmoothing smoothing;
  smoothing.variant = variant;
  smoothing.entry_distance = entry;
  smoothing.exit_distance = exit;
  smoothing.arcs.push_back(
      PathPrimitive::arc(o1, r, polarAngle(i1 - o1), -s * first).withVariant(variant));
  smoothing.arcs.push_back(
      PathPrimitive::arc(o2, r, polarAngle(i12 - o2), s * middle).withVariant(variant));
  smoothing.arcs.push_back(
      PathPrimitive::arc(o3, r, polarAngle(i23 - o3), -s * first).withVariant(variant));
  return smoothing;
}

}  // namespace kinematic_coverage::core
