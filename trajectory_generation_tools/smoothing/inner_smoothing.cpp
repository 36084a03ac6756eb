#include "trajectory_generation_tools/smoothing/inner_smoothing.h"

#include <cmath>

#include "trajectory_generation_tools/smoothing/corner_geometry.h"

namespace kinematic_coverage::core {

std::optional<CornerSmoothing> InnerSmoothing::compute(const Corner& corner) {
  const std::optional<CornerGeometry> geometry = CornerGeometry::of(corner);
  if (!geometry || geometry->isStraight() || geometry->isReversal()) return std::nullopt;
  const CornerGeometry& g = *geometry;
  const double r = g.radius();

  // Alg. 2: alpha = angle ABO = ABC / 2 and d = |BO| = r / sin(alpha). Decision: the centre
  // is B + d * normalize(u_BA + u_BC) (the inner bisector) instead of picking the one of two
  // candidates closer to AC, which is fragile near straight corners. alpha is at least
  // kReversalTolerance / 2 here, so sin(alpha) > 0.
  const double alpha = 0.5 * g.interiorAngle();
  const double d = r / std::sin(alpha);
  const Point2 centre = g.b() + d * g.innerBisector();

  // Alg. 3: the tangent points I1, I2 (Eq. 3.1: both legs at distance r from O) are the
  // projections of the centre onto the legs' lines; the arc turns the way the path turns
  // (counter-clockwise for cross(AB, BC) > 0) through the whole heading change.
  const double entry = g.alongBA(centre);
  const double exit = g.alongBC(centre);
  const Point2 start = g.b() + entry * g.towardA();
  const Point2 radial = start - centre;
  CornerSmoothing smoothing;
  smoothing.variant = SmoothingVariant::kInner;
  smoothing.entry_distance = entry;
  smoothing.exit_distance = exit;
  smoothing.arcs.push_back(
      PathPrimitive::arc(centre, r, std::atan2(radial.y(), radial.x()), g.side() * g.turn())
          .withVariant(SmoothingVariant::kInner));
  return smoothing;
}

}  // namespace kinematic_coverage::core
