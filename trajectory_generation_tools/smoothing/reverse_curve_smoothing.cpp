#include "trajectory_generation_tools/smoothing/reverse_curve_smoothing.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "trajectory_generation_tools/smoothing/corner_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// Entry distances tried along the incoming leg before refining the best.
constexpr int kEntrySamples = 128;
/// Refinement steps of the golden-section search around the best sample.
constexpr int kRefinementSteps = 40;
/// Arcs sweeping less than this (rad) make no curve (the corner would be straight).
constexpr double kMinSweep = 1e-9;

/// One member of the family of reverse curves: its arcs and where it touches the legs.
struct Curve {
  bool valid = false;
  Point2 o1 = Point2::Zero();
  Point2 o2 = Point2::Zero();
  Point2 t1 = Point2::Zero();
  Point2 t2 = Point2::Zero();
  double entry = 0.0;
  double exit = 0.0;
  double sweep1 = 0.0;
  double sweep2 = 0.0;
  Point2 inflection() const { return 0.5 * (o1 + o2); }
};

class CurveFamily {
 public:
  CurveFamily(const Point2& b1, const Point2& b2, const Point2& d1, const Point2& d3, double side,
              double radius)
      : b1_(b1), b2_(b2), d1_(d1), d3_(d3), side_(side), radius_(radius) {}

  /// The curve whose first arc leaves the incoming line `entry` before b1.
  Curve at(double entry) const {
    Curve best;
    const double r = radius_;
    const Point2 t1 = b1_ - entry * d1_;
    const Point2 o1 = t1 + r * side_ * leftNormal(d1_);
    const Point2 q = b2_ - r * side_ * leftNormal(d3_) - o1;
    const double half_b = q.dot(d3_);
    const double discriminant = half_b * half_b - q.squaredNorm() + 4.0 * r * r;
    if (discriminant < 0.0) return best;
    for (const double sign : {-1.0, 1.0}) {
      Curve curve;
      curve.exit = -half_b + sign * std::sqrt(discriminant);
      if (curve.exit < 0.0) continue;
      curve.entry = entry;
      curve.t1 = t1;
      curve.o1 = o1;
      curve.t2 = b2_ + curve.exit * d3_;
      curve.o2 = curve.t2 - r * side_ * leftNormal(d3_);
      const Point2 inflection = curve.inflection();
      curve.sweep1 = sweepBetween(polarAngle(t1 - o1), polarAngle(inflection - o1), side_);
      curve.sweep2 =
          sweepBetween(polarAngle(inflection - curve.o2), polarAngle(curve.t2 - curve.o2), -side_);
      if (curve.sweep1 < kMinSweep || curve.sweep2 < kMinSweep || curve.sweep1 >= M_PI ||
          curve.sweep2 >= M_PI) {
        continue;
      }
      curve.valid = true;
      if (!best.valid || curve.sweep1 + curve.sweep2 < best.sweep1 + best.sweep2) best = curve;
    }
    return best;
  }

 private:
  Point2 b1_, b2_, d1_, d3_;
  double side_;
  double radius_;
};

}  // namespace

std::optional<CornerSmoothing> ReverseCurveSmoothing::compute(const Point2& a, const Point2& b1,
                                                              const Point2& b2, const Point2& c,
                                                              double radius) {
  if (!(std::isfinite(radius) && radius > 0.0) || !a.allFinite() || !b1.allFinite() ||
      !b2.allFinite() || !c.allFinite()) {
    return std::nullopt;
  }
  const double incoming_length = (b1 - a).norm();
  const double middle_length = (b2 - b1).norm();
  const double outgoing_length = (c - b2).norm();
  if (incoming_length <= 0.0 || middle_length <= 0.0 || outgoing_length <= 0.0 ||
      middle_length > kMaxMiddleLegRadii * radius) {
    return std::nullopt;
  }
  const Point2 d1 = (b1 - a) / incoming_length;
  const Point2 d2 = (b2 - b1) / middle_length;
  const Point2 d3 = (c - b2) / outgoing_length;
  const double first_turn = d1.x() * d2.y() - d1.y() * d2.x();
  const double second_turn = d2.x() * d3.y() - d2.y() * d3.x();
  if (first_turn == 0.0 || second_turn == 0.0 || (first_turn > 0.0) == (second_turn > 0.0)) {
    return std::nullopt;
  }
  // A middle leg that runs back against the incoming or outgoing one makes an excursion
  // (a sweep's extension) that the curve would cut off; only sideways jogs qualify.
  if (d1.dot(d2) < -kMaxBackwardCosine || d2.dot(d3) < -kMaxBackwardCosine) return std::nullopt;
  const double side = first_turn > 0.0 ? 1.0 : -1.0;
  const CurveFamily family(b1, b2, d1, d3, side, radius);
  const Point2 middle = 0.5 * (b1 + b2);
  const auto miss = [&](const Curve& curve) {
    return curve.valid && curve.exit <= outgoing_length ? (curve.inflection() - middle).norm()
                                                        : std::numeric_limits<double>::infinity();
  };

  // The family is one-dimensional in the entry distance: sample it, then refine around the
  // best sample (golden section on the distance of the inflection point from the middle).
  const double range = std::min(incoming_length, middle_length + 4.0 * radius);
  double best_entry = -1.0;
  double best_miss = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= kEntrySamples; ++k) {
    const double entry = range * k / kEntrySamples;
    const double m = miss(family.at(entry));
    if (m < best_miss) {
      best_miss = m;
      best_entry = entry;
    }
  }
  if (best_entry < 0.0) return std::nullopt;
  double low = std::max(0.0, best_entry - range / kEntrySamples);
  double high = std::min(range, best_entry + range / kEntrySamples);
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int step = 0; step < kRefinementSteps; ++step) {
    const double left = high - golden * (high - low);
    const double right = low + golden * (high - low);
    if (miss(family.at(left)) <= miss(family.at(right))) {
      high = right;
    } else {
      low = left;
    }
  }
  Curve curve = family.at(0.5 * (low + high));
  if (!(miss(curve) <= best_miss)) curve = family.at(best_entry);
  if (!std::isfinite(miss(curve))) return std::nullopt;

  CornerSmoothing smoothing;
  smoothing.variant = SmoothingVariant::kReverseCurve;
  smoothing.corners = 2;
  smoothing.entry_distance = curve.entry;
  smoothing.exit_distance = curve.exit;
  const Point2 inflection = curve.inflection();
  smoothing.arcs.push_back(
      PathPrimitive::arc(curve.o1, radius, polarAngle(curve.t1 - curve.o1), side * curve.sweep1)
          .withVariant(SmoothingVariant::kReverseCurve));
  smoothing.arcs.push_back(
      PathPrimitive::arc(curve.o2, radius, polarAngle(inflection - curve.o2), -side * curve.sweep2)
          .withVariant(SmoothingVariant::kReverseCurve));
  return smoothing;
}

}  // namespace kinematic_coverage::core
