#include "trajectory_generation_tools/smoothing/corner_geometry.h"

#include <algorithm>
#include <cmath>

namespace kinematic_coverage::core {
namespace {

bool finite(const Point2& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }

/// The vector rotated by +90 degrees (its left normal).
Point2 leftOf(const Point2& v) { return {-v.y(), v.x()}; }

}  // namespace

std::optional<CornerGeometry> CornerGeometry::of(const Corner& corner) {
  if (!finite(corner.a) || !finite(corner.b) || !finite(corner.c) || !finite(corner.incoming) ||
      !std::isfinite(corner.radius) || corner.radius <= 0.0) {
    return std::nullopt;
  }
  CornerGeometry g;
  g.b_ = corner.b;
  g.radius_ = corner.radius;
  g.length_ba_ = (corner.a - corner.b).norm();
  g.length_bc_ = (corner.c - corner.b).norm();
  if (!(g.length_bc_ > 0.0)) return std::nullopt;
  g.toward_c_ = (corner.c - corner.b) / g.length_bc_;
  const double incoming_norm = corner.incoming.norm();
  if (incoming_norm > 0.0) {
    g.toward_a_ = -corner.incoming / incoming_norm;
  } else if (g.length_ba_ > 0.0) {
    g.toward_a_ = (corner.a - corner.b) / g.length_ba_;
  } else {
    return std::nullopt;
  }
  const Point2 travel_in = -g.toward_a_;
  const Point2& travel_out = g.toward_c_;
  const double turn_cross = travel_in.x() * travel_out.y() - travel_in.y() * travel_out.x();
  g.turn_ = std::atan2(std::abs(turn_cross), travel_in.dot(travel_out));
  g.side_ = turn_cross >= 0.0 ? 1.0 : -1.0;

  // The inner bisector is normalize(u_BA + u_BC). That sum vanishes for straight corners,
  // so for heading changes up to pi/2 the equal vector side * left(normalize(travel_in +
  // travel_out)) is used instead (perpendicular to u_BC - u_BA, which is well conditioned).
  const Point2 sum = g.toward_a_ + g.toward_c_;
  const Point2 mean_travel = travel_in + travel_out;
  if (g.turn_ <= M_PI_2 && mean_travel.norm() > 0.0) {
    g.inner_bisector_ = g.side_ * leftOf(mean_travel.normalized());
  } else if (sum.norm() > 0.0) {
    g.inner_bisector_ = sum.normalized();
  } else {
    g.inner_bisector_ = g.toward_a_;
  }
  // The inner side lies left of travel for a left turn; the outer normals point away.
  g.outer_normal_ba_ = -g.side_ * leftOf(travel_in);
  g.outer_normal_bc_ = -g.side_ * leftOf(travel_out);
  g.scale_ = std::max({g.length_ba_, g.length_bc_, g.radius_, corner.b.norm(), 1e-300});
  return g;
}

Point2 CornerGeometry::mirrored(const Point2& p) const {
  const Point2 rel = p - b_;
  return b_ + 2.0 * rel.dot(inner_bisector_) * inner_bisector_ - rel;
}

Point2 leftNormal(const Point2& d) { return {-d.y(), d.x()}; }

double polarAngle(const Point2& v) { return std::atan2(v.y(), v.x()); }

double sweepBetween(double from, double to, double side) {
  double sweep = std::fmod(side * (to - from), 2.0 * M_PI);
  if (sweep < 0.0) sweep += 2.0 * M_PI;
  return sweep;
}

}  // namespace kinematic_coverage::core
