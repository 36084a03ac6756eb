#include "trajectory_generation_tools/smoothing/outer_smoothing_bisector.h"

#include <cmath>

#include "trajectory_generation_tools/smoothing/corner_geometry.h"
#include "trajectory_generation_tools/smoothing/outer_arc_chain.h"

namespace kinematic_coverage::core {
namespace {

/// Relative slack (times r^2) for a negative discriminant that is only rounding.
constexpr double kDiscriminantSlack = 1e-12;
/// Relative slack (times r) on the circle-overlap condition |O1O3| >= 2r.
constexpr double kOverlapSlack = 1e-12;

}  // namespace

std::optional<CornerSmoothing> OuterSmoothingBisector::compute(const Corner& corner) {
  const std::optional<CornerGeometry> geometry = CornerGeometry::of(corner);
  if (!geometry || geometry->isStraight()) return std::nullopt;
  const CornerGeometry& g = *geometry;
  const double r = g.radius();

  // Eq. 3.3 at its optimum |BO2| = r. Decision: O2 lies on the corner's inner side of B
  // (B + r * inner bisector, as Fig. 3.5 shows), so the middle circle passes through B.
  const Point2 o2 = g.b() + r * g.innerBisector();

  // Alg. 4 / Eq. 3.4 in the unknowns (x, y), the coordinates of O3 along BC and along BC's
  // outer normal: |y| = r (the distance condition is on the unknown centre, not on O2 as
  // the thesis prints it) and (x - x2)^2 + (y - y2)^2 = 4r^2. Decision: the side test uses
  // the line's orientation: O3 must lie on the other side of the oriented line BC than O2,
  // which is the outer side, y = r (O2's y2 = -r sin(ABC/2) <= 0; for an exact reversal O2
  // is on the line and the outer side is taken). Of the two remaining solutions
  // x = x2 +- sqrt(.), the thesis keeps the one closest to AC; we keep x2 + sqrt(.), since the
  // other one's tangent point lies at or behind B (x2 - sqrt(.) <= 0) and never on BC.
  const double x2 = g.alongBC(o2);
  const double y2 = (o2 - g.b()).dot(g.outerNormalBC());
  const double discriminant = 4.0 * r * r - (r - y2) * (r - y2);
  if (discriminant < -kDiscriminantSlack * r * r) return std::nullopt;
  const double x3 = x2 + std::sqrt(std::max(0.0, discriminant));
  const Point2 o3 = g.b() + x3 * g.towardC() + r * g.outerNormalBC();
  // Alg. 5: O1 is O3 mirrored across the bisector.
  const Point2 o1 = g.mirrored(o3);
  // Decision: as Alg. 8 does for its variant, the outer circles must not overlap.
  if ((o1 - o3).norm() < 2.0 * r * (1.0 - kOverlapSlack)) return std::nullopt;
  return OuterArcChain::build(g, o1, o2, o3, SmoothingVariant::kOuterBisector);
}

}  // namespace kinematic_coverage::core
