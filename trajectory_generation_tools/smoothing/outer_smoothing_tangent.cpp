#include "trajectory_generation_tools/smoothing/outer_smoothing_tangent.h"

#include <cmath>

#include "trajectory_generation_tools/smoothing/corner_geometry.h"
#include "trajectory_generation_tools/smoothing/outer_arc_chain.h"

namespace kinematic_coverage::core {

std::optional<CornerSmoothing> OuterSmoothingTangent::compute(const Corner& corner) {
  const std::optional<CornerGeometry> geometry = CornerGeometry::of(corner);
  if (!geometry || geometry->isStraight()) return std::nullopt;
  const CornerGeometry& g = *geometry;
  const double r = g.radius();

  // Alg. 8: the circle of the shorter leg first; a tie |AB| = |BC| takes the else branch
  // (C's circle first), as written, which is deterministic. Alg. 6 / Eq. 3.6: that circle's
  // centre is on the perpendicular to the leg through its far end, at distance r from the
  // leg: of the two solutions the one furthest from the waypoint on the other leg, which is
  // the one on the corner's outer side. The other outer circle is its mirror image.
  Point2 o1;
  Point2 o3;
  if (g.lengthBA() < g.lengthBC()) {
    o1 = g.b() + g.lengthBA() * g.towardA() + r * g.outerNormalBA();
    o3 = g.mirrored(o1);
  } else {
    o3 = g.b() + g.lengthBC() * g.towardC() + r * g.outerNormalBC();
    o1 = g.mirrored(o3);
  }
  // Alg. 8 (Eq. 3.5): the outer circles neither overlap nor lie too far apart for the
  // middle circle to touch both; strict inequalities as written.
  const double spread = (o1 - o3).norm();
  if (!(spread > 2.0 * r && spread < 4.0 * r)) return std::nullopt;

  // Alg. 7 / Eq. 3.7: O2 on the bisector line at distance 2r from O1: its foot F on the
  // bisector plus or minus sqrt(4r^2 - |O1F|^2) along it. As written, the solution furthest
  // from AC, which is the one on the corner's outer side (towards -bisector).
  const Point2 foot = g.b() + (o1 - g.b()).dot(g.innerBisector()) * g.innerBisector();
  const double half_spread = (o1 - foot).norm();
  const double discriminant = 4.0 * r * r - half_spread * half_spread;
  if (!(discriminant > 0.0)) return std::nullopt;
  const Point2 o2 = foot - std::sqrt(discriminant) * g.innerBisector();
  return OuterArcChain::build(g, o1, o2, o3, SmoothingVariant::kOuterTangent);
}

}  // namespace kinematic_coverage::core
