#pragma once

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// What a primitive is: a straight segment, a circular arc, or a turn on the spot.
enum class PrimitiveKind { kSegment, kArc, kRotation };

/// Which smoothing made a primitive: Algorithm 1's variants, or the reverse curve of the
/// global strategy (ReverseCurveSmoothing). kNone: the planner's own segment or a sharp
/// corner's rotation, or a segment joining two smoothings.
enum class SmoothingVariant { kNone, kInner, kOuterBisector, kOuterTangent, kReverseCurve, kBulb };

/// One piece of a drivable path, with exact length and pose at any point along it.
/// Arcs are stored by centre, radius, the polar angle of their start point about the
/// centre and a signed sweep (positive: counter-clockwise); rotations by position, start
/// heading and signed turn.
class PathPrimitive {
 public:
  /// A straight segment from `from` to `to` (zero length allowed).
  static PathPrimitive segment(const Point2& from, const Point2& to);
  /// An arc of `radius` (> 0) about `centre`, from polar angle `start_angle`, sweeping
  /// `sweep` radians (positive counter-clockwise).
  static PathPrimitive arc(const Point2& centre, double radius, double start_angle, double sweep);
  /// A turn on the spot at `at` from heading `start_yaw` by the signed angle `turn`.
  static PathPrimitive rotation(const Point2& at, double start_yaw, double turn);

  PrimitiveKind kind() const { return kind_; }
  SmoothingVariant variant() const { return variant_; }
  /// Tags the primitive with the smoothing that made it.
  PathPrimitive& withVariant(SmoothingVariant variant) {
    variant_ = variant;
    return *this;
  }

  /// Metres along the path (0 for a rotation).
  double length() const;
  /// The absolute heading change (|sweep| for an arc, |turn| for a rotation, 0 for a segment).
  double turnAngle() const;
  /// 1 / radius for an arc, 0 for a segment; a rotation has no finite curvature.
  double curvature() const;

  /// The pose at `fraction` in [0, 1] of the primitive (of its length, or of its turn for
  /// a rotation); the yaw is the heading of travel, wrapped into (-pi, pi].
  Pose2 poseAt(double fraction) const;
  Pose2 startPose() const { return poseAt(0.0); }
  Pose2 endPose() const { return poseAt(1.0); }

  // Geometry, for collision checks and markers.
  const Point2& start() const { return start_; }
  const Point2& end() const { return end_; }
  const Point2& centre() const { return centre_; }
  double radius() const { return radius_; }
  double startAngle() const { return start_angle_; }
  double sweep() const { return sweep_; }

 private:
  PrimitiveKind kind_ = PrimitiveKind::kSegment;
  SmoothingVariant variant_ = SmoothingVariant::kNone;
  Point2 start_ = Point2::Zero();
  Point2 end_ = Point2::Zero();
  Point2 centre_ = Point2::Zero();  ///< arc only
  double radius_ = 0.0;             ///< arc only
  double start_angle_ = 0.0;        ///< arc: polar angle of start; rotation: start heading
  double sweep_ = 0.0;              ///< arc: signed sweep; rotation: signed turn
};

}  // namespace kinematic_coverage::core
