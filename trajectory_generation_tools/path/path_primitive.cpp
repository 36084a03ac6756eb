#include "trajectory_generation_tools/path/path_primitive.h"

#include <algorithm>
#include <cmath>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {

PathPrimitive PathPrimitive::segment(const Point2& from, const Point2& to) {
  PathPrimitive primitive;
  primitive.kind_ = PrimitiveKind::kSegment;
  primitive.start_ = from;
  primitive.end_ = to;
  return primitive;
}

PathPrimitive PathPrimitive::arc(const Point2& centre, double radius, double start_angle,
                                 double sweep) {
  PathPrimitive primitive;
  primitive.kind_ = PrimitiveKind::kArc;
  primitive.centre_ = centre;
  primitive.radius_ = radius;
  primitive.start_angle_ = start_angle;
  primitive.sweep_ = sweep;
  primitive.start_ = centre + radius * Point2(std::cos(start_angle), std::sin(start_angle));
  primitive.end_ =
      centre + radius * Point2(std::cos(start_angle + sweep), std::sin(start_angle + sweep));
  return primitive;
}

PathPrimitive PathPrimitive::rotation(const Point2& at, double start_yaw, double turn) {
  PathPrimitive primitive;
  primitive.kind_ = PrimitiveKind::kRotation;
  primitive.start_ = at;
  primitive.end_ = at;
  primitive.start_angle_ = start_yaw;
  primitive.sweep_ = turn;
  return primitive;
}

double PathPrimitive::length() const {
  switch (kind_) {
    case PrimitiveKind::kSegment:
      return (end_ - start_).norm();
    case PrimitiveKind::kArc:
      return radius_ * std::abs(sweep_);
    case PrimitiveKind::kRotation:
      return 0.0;
  }
  return 0.0;
}

double PathPrimitive::turnAngle() const {
  return kind_ == PrimitiveKind::kSegment ? 0.0 : std::abs(sweep_);
}

double PathPrimitive::curvature() const {
  return kind_ == PrimitiveKind::kArc ? 1.0 / radius_ : 0.0;
}

Pose2 PathPrimitive::poseAt(double fraction) const {
  const double f = std::clamp(fraction, 0.0, 1.0);
  switch (kind_) {
    case PrimitiveKind::kSegment: {
      const Point2 p = start_ + f * (end_ - start_);
      const double yaw = (end_ - start_).squaredNorm() > 0.0 ? headingOf(start_, end_) : 0.0;
      return {p.x(), p.y(), yaw};
    }
    case PrimitiveKind::kArc: {
      const double angle = start_angle_ + f * sweep_;
      const Point2 p = centre_ + radius_ * Point2(std::cos(angle), std::sin(angle));
      const double yaw = wrapAngle(angle + (sweep_ >= 0.0 ? M_PI_2 : -M_PI_2));
      return {p.x(), p.y(), yaw};
    }
    case PrimitiveKind::kRotation:
      return {start_.x(), start_.y(), wrapAngle(start_angle_ + f * sweep_)};
  }
  return {};
}

}  // namespace kinematic_coverage::core
