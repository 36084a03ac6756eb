#include "trajectory_generation_tools/path/path_primitive.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// Largest heading change over one piece of a clothoid's numerical integration, radians:
/// the 5-point Gauss-Legendre rule is then exact to about 1e-15 per metre.
constexpr double kClothoidPieceTurn = 0.2;

/// The offset from a clothoid's start to its point `s` metres along it (start heading
/// `yaw`, curvature `k0`, rate `rate`): the integral of the unit tangent, by composite
/// 5-point Gauss-Legendre quadrature.
Point2 clothoidOffset(double yaw, double k0, double rate, double s) {
  if (!(s > 0.0)) return Point2::Zero();
  static constexpr double kNodes[5] = {-0.9061798459386640, -0.5384693101056831, 0.0,
                                       0.5384693101056831, 0.9061798459386640};
  static constexpr double kWeights[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                         0.4786286704993665, 0.2369268850561891};
  const double largest_curvature = std::max(std::abs(k0), std::abs(k0 + rate * s));
  const int pieces =
      std::max(1, static_cast<int>(std::ceil(largest_curvature * s / kClothoidPieceTurn)));
  const double h = s / pieces;
  Point2 sum = Point2::Zero();
  for (int piece = 0; piece < pieces; ++piece) {
    const double middle = (piece + 0.5) * h;
    for (int k = 0; k < 5; ++k) {
      const double u = middle + 0.5 * h * kNodes[k];
      const double heading = yaw + k0 * u + 0.5 * rate * u * u;
      sum += kWeights[k] * Point2(std::cos(heading), std::sin(heading));
    }
  }
  return 0.5 * h * sum;
}

}  // namespace

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

PathPrimitive PathPrimitive::clothoid(const Pose2& start, double start_curvature,
                                      double curvature_rate, double length) {
  PathPrimitive primitive;
  primitive.kind_ = PrimitiveKind::kClothoid;
  primitive.start_ = start.position();
  primitive.start_angle_ = start.yaw;
  primitive.start_curvature_ = start_curvature;
  primitive.curvature_rate_ = curvature_rate;
  primitive.length_ = length;
  primitive.sweep_ = start_curvature * length + 0.5 * curvature_rate * length * length;
  const double largest =
      std::max(std::abs(start_curvature), std::abs(start_curvature + curvature_rate * length));
  primitive.radius_ = largest > 0.0 ? 1.0 / largest : std::numeric_limits<double>::infinity();
  primitive.end_ =
      primitive.start_ + clothoidOffset(start.yaw, start_curvature, curvature_rate, length);
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
    case PrimitiveKind::kClothoid:
      return length_;
  }
  return 0.0;
}

double PathPrimitive::turnAngle() const {
  return kind_ == PrimitiveKind::kSegment ? 0.0 : std::abs(sweep_);
}

double PathPrimitive::curvature() const {
  return kind_ == PrimitiveKind::kArc || kind_ == PrimitiveKind::kClothoid ? 1.0 / radius_ : 0.0;
}

double PathPrimitive::curvatureAt(double fraction) const {
  const double f = std::clamp(fraction, 0.0, 1.0);
  switch (kind_) {
    case PrimitiveKind::kArc:
      return sweep_ >= 0.0 ? 1.0 / radius_ : -1.0 / radius_;
    case PrimitiveKind::kClothoid:
      return start_curvature_ + curvature_rate_ * f * length_;
    case PrimitiveKind::kSegment:
    case PrimitiveKind::kRotation:
      return 0.0;
  }
  return 0.0;
}

std::vector<Point2> PathPrimitive::polyline(double tolerance) const {
  if (kind_ == PrimitiveKind::kSegment) return {start_, end_};
  if (kind_ == PrimitiveKind::kRotation) return {start_};
  // A chord of length l of a curve of curvature at most k stays within l^2 k / 8 of it.
  const double k = curvature();
  const double chord = k > 0.0 ? std::sqrt(8.0 * tolerance / k) : length();
  const int pieces = std::max(1, static_cast<int>(std::ceil(length() / std::max(chord, 1e-12))));
  std::vector<Point2> points;
  points.reserve(static_cast<std::size_t>(pieces) + 1);
  for (int i = 0; i <= pieces; ++i) {
    points.push_back(i == pieces ? end_ : poseAt(static_cast<double>(i) / pieces).position());
  }
  return points;
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
    case PrimitiveKind::kClothoid: {
      if (f == 1.0) {
        return {end_.x(), end_.y(), wrapAngle(start_angle_ + sweep_)};
      }
      const double s = f * length_;
      const Point2 p = start_ + clothoidOffset(start_angle_, start_curvature_, curvature_rate_, s);
      return {p.x(), p.y(),
              wrapAngle(start_angle_ + start_curvature_ * s + 0.5 * curvature_rate_ * s * s)};
    }
  }
  return {};
}

}  // namespace kinematic_coverage::core
