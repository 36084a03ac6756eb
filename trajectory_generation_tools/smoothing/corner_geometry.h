#pragma once

#include <optional>

#include "trajectory_generation_tools/smoothing/corner.h"

namespace kinematic_coverage::core {

/// Below this heading change (rad) a corner is straight: no turn, nothing to smooth.
constexpr double kStraightTurnTolerance = 1e-9;
/// Above pi minus this heading change (rad) a corner is a reversal: the inscribed circle of
/// the inner smoothing would lie ~r / sin(angle / 2) away, so inner smoothing is infeasible.
constexpr double kReversalTolerance = 1e-6;
/// Relative tolerance (times the corner's scale) for "a tangent point lies on its leg".
constexpr double kLegTolerance = 1e-9;

/// The derived geometry of a Corner that all three smoothings share: unit leg directions,
/// the heading change and its side, the inner bisector and the legs' outer normals.
/// Angles come from atan2 of cross and dot products (equivalent to the law of cosines of
/// Eq. 3.2, but without acos and well conditioned near 0 and pi).
class CornerGeometry {
 public:
  /// The geometry of `corner`; nullopt when a coordinate or the radius is not finite, the
  /// radius is not positive, or a leg has no direction (B == C, or A == B without an
  /// incoming direction).
  static std::optional<CornerGeometry> of(const Corner& corner);

  const Point2& b() const { return b_; }
  double radius() const { return radius_; }
  /// Unit vector from B towards A (u_BA) and from B towards C (u_BC).
  const Point2& towardA() const { return toward_a_; }
  const Point2& towardC() const { return toward_c_; }
  /// Leg lengths |BA| (from the effective A) and |BC|.
  double lengthBA() const { return length_ba_; }
  double lengthBC() const { return length_bc_; }
  /// Heading change at B in [0, pi]; the interior angle ABC is pi minus it.
  double turn() const { return turn_; }
  double interiorAngle() const { return M_PI - turn_; }
  /// +1 when the path turns left (counter-clockwise) at B, -1 when right; an exact
  /// reversal turns left (a deterministic choice of side).
  double side() const { return side_; }
  /// Unit bisector of ABC pointing into the corner's inner side.
  const Point2& innerBisector() const { return inner_bisector_; }
  /// Unit normals of the lines AB and BC pointing to the corner's outer side.
  const Point2& outerNormalBA() const { return outer_normal_ba_; }
  const Point2& outerNormalBC() const { return outer_normal_bc_; }
  /// Length scale of the corner (largest of |BA|, |BC|, r, |B|) for relative tolerances.
  double scale() const { return scale_; }

  bool isStraight() const { return turn_ <= kStraightTurnTolerance; }
  bool isReversal() const { return turn_ >= M_PI - kReversalTolerance; }

  /// The reflection of `p` across the bisector line of ABC (mirrored_point of Alg. 5, 8).
  Point2 mirrored(const Point2& p) const;
  /// The projection of `p` onto the line AB / BC as a distance from B along the leg.
  double alongBA(const Point2& p) const { return (p - b_).dot(toward_a_); }
  double alongBC(const Point2& p) const { return (p - b_).dot(toward_c_); }

 private:
  CornerGeometry() = default;

  Point2 b_ = Point2::Zero();
  double radius_ = 0.0;
  Point2 toward_a_ = Point2::Zero();
  Point2 toward_c_ = Point2::Zero();
  double length_ba_ = 0.0;
  double length_bc_ = 0.0;
  double turn_ = 0.0;
  double side_ = 1.0;
  Point2 inner_bisector_ = Point2::Zero();
  Point2 outer_normal_ba_ = Point2::Zero();
  Point2 outer_normal_bc_ = Point2::Zero();
  double scale_ = 1.0;
};

/// `d` turned a quarter to the left (counter-clockwise), its length kept.
Point2 leftNormal(const Point2& d);
/// The polar angle of `v` about the origin, in (-pi, pi].
double polarAngle(const Point2& v);
/// The angle swept turning `side` (+1 counter-clockwise, -1 clockwise) from polar angle
/// `from` to polar angle `to`, in [0, 2 pi): how far an arc of that side runs between them.
double sweepBetween(double from, double to, double side);

}  // namespace kinematic_coverage::core
