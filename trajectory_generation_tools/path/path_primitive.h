#pragma once

#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// What a primitive is: a straight segment, a circular arc, a turn on the spot, or a
/// clothoid (curvature changing linearly with length, `turn_curve: clothoid`).
enum class PrimitiveKind { kSegment, kArc, kRotation, kClothoid };

/// Which smoothing made a primitive: Algorithm 1's variants, or the reverse curve of the
/// global strategy (ReverseCurveSmoothing). kNone: the planner's own segment or a sharp
/// corner's rotation, or a segment joining two smoothings.
enum class SmoothingVariant { kNone, kInner, kOuterBisector, kOuterTangent, kReverseCurve, kBulb };

/// One piece of a drivable path, with exact length and pose at any point along it.
/// Arcs are stored by centre, radius, the polar angle of their start point about the
/// centre and a signed sweep (positive: counter-clockwise); rotations by position, start
/// heading and signed turn; clothoids by start pose, start curvature, curvature rate and
/// length, their points integrated numerically (Fresnel integrals, to about 1e-12 m).
class PathPrimitive {
 public:
  /// A straight segment from `from` to `to` (zero length allowed).
  static PathPrimitive segment(const Point2& from, const Point2& to);
  /// An arc of `radius` (> 0) about `centre`, from polar angle `start_angle`, sweeping
  /// `sweep` radians (positive counter-clockwise).
  static PathPrimitive arc(const Point2& centre, double radius, double start_angle, double sweep);
  /// A turn on the spot at `at` from heading `start_yaw` by the signed angle `turn`.
  static PathPrimitive rotation(const Point2& at, double start_yaw, double turn);
  /// A clothoid from `start` (position and heading) of `length` (>= 0) m whose signed
  /// curvature (positive: turning counter-clockwise) is `start_curvature` at the start and
  /// changes by `curvature_rate` (1/m^2) per metre.
  static PathPrimitive clothoid(const Pose2& start, double start_curvature, double curvature_rate,
                                double length);

  PrimitiveKind kind() const { return kind_; }
  SmoothingVariant variant() const { return variant_; }
  /// Tags the primitive with the smoothing that made it.
  PathPrimitive& withVariant(SmoothingVariant variant) {
    variant_ = variant;
    return *this;
  }

  /// Metres along the path (0 for a rotation).
  double length() const;
  /// The absolute heading change (|sweep| for an arc, |turn| for a rotation, 0 for a
  /// segment, |end heading - start heading| unwrapped for a clothoid).
  double turnAngle() const;
  /// 1 / radius for an arc, 0 for a segment, the largest |curvature| of a clothoid (at one
  /// of its ends); a rotation has no finite curvature.
  double curvature() const;
  /// The signed curvature at `fraction` in [0, 1] of the primitive's length (1/m; 0 for a
  /// segment and a rotation).
  double curvatureAt(double fraction) const;

  /// The pose at `fraction` in [0, 1] of the primitive (of its length, or of its turn for
  /// a rotation); the yaw is the heading of travel, wrapped into (-pi, pi].
  Pose2 poseAt(double fraction) const;
  Pose2 startPose() const { return poseAt(0.0); }
  Pose2 endPose() const { return poseAt(1.0); }

  /// Points along the primitive, its start and end included, equally spaced along it, such
  /// that it lies within `tolerance` (m, > 0) of the polyline through them: a segment's
  /// ends, a rotation's position, an arc's or a clothoid's chords. For the distance,
  /// clearance and drawing of curves that have no closed form.
  std::vector<Point2> polyline(double tolerance) const;

  // Geometry, for collision checks and markers.
  const Point2& start() const { return start_; }
  const Point2& end() const { return end_; }
  const Point2& centre() const { return centre_; }
  /// An arc's radius; a clothoid's smallest radius of curvature (1 / curvature(), infinite
  /// for a straight clothoid).
  double radius() const { return radius_; }
  /// An arc's start polar angle; a rotation's or a clothoid's start heading.
  double startAngle() const { return start_angle_; }
  /// An arc's signed sweep, a rotation's signed turn, a clothoid's signed heading change.
  double sweep() const { return sweep_; }
  /// A clothoid's signed curvature at its start, and its curvature rate (1/m^2).
  double startCurvature() const { return start_curvature_; }
  double curvatureRate() const { return curvature_rate_; }

 private:
  PrimitiveKind kind_ = PrimitiveKind::kSegment;
  SmoothingVariant variant_ = SmoothingVariant::kNone;
  Point2 start_ = Point2::Zero();
  Point2 end_ = Point2::Zero();
  Point2 centre_ = Point2::Zero();  ///< arc only
  double radius_ = 0.0;             ///< arc only
  double start_angle_ = 0.0;        ///< arc: polar angle of start; rotation: start heading
  double sweep_ = 0.0;              ///< arc: signed sweep; rotation: signed turn
  double start_curvature_ = 0.0;    ///< clothoid only
  double curvature_rate_ = 0.0;     ///< clothoid only
  double length_ = 0.0;             ///< clothoid only
};

}  // namespace kinematic_coverage::core
