#pragma once

#include <algorithm>
#include <cmath>

#include "polygon_coverage_ros_bridge/base/vehicle_limits.h"

namespace kinematic_coverage::core {

/// The velocity model of the whole package (Thesis section 3.3): along a path the speed
/// changes at most at a_max and stays at most at a speed limit (v_max on a segment, the
/// arc speed on an arc), so a piece is driven accelerate-cruise-brake, a trapezoid. The
/// planner's segment cost, the smoother's corner times and the trajectory's time stamps
/// all come from this one class. It does not check its limits: the stages that take
/// VehicleLimits from the user check them (the parameter schema, checkParameters).
class TrapezoidalVelocityProfile {
 public:
  explicit TrapezoidalVelocityProfile(const VehicleLimits& limits)
      : v_max_(limits.v_max), a_max_(limits.a_max) {}

  /// Seconds over a straight `length` from rest to rest: L / v + v / a when the segment is
  /// long enough to cruise (L >= v^2 / a), else 2 sqrt(L / a) (a triangle).
  double restToRestTime(double length) const {
    const double cruise_length = v_max_ * v_max_ / a_max_;
    if (length >= cruise_length) return length / v_max_ + v_max_ / a_max_;
    return 2.0 * std::sqrt(length / a_max_);
  }

  /// The highest speed reachable over `length` from speed `from` (v^2 grows by at most
  /// 2 a_max per metre).
  double reachableSpeed(double from, double length) const {
    return std::sqrt(from * from + 2.0 * a_max_ * length);
  }

  /// The highest speed on a piece of `length` entered at `entry` and left at `exit`,
  /// at most `limit`: where accelerating from `entry` meets braking to `exit`.
  double peakSpeed(double entry, double exit, double length, double limit) const {
    return std::min(limit, std::sqrt((entry * entry + exit * exit + 2.0 * a_max_ * length) / 2.0));
  }

  /// Metres to change speed from `from` to `to` at a_max (negative when `to` < `from`).
  double changeDistance(double from, double to) const {
    return (to * to - from * from) / (2.0 * a_max_);
  }

  /// Fastest seconds over a straight piece of `length` from speed `entry` to speed `exit`
  /// under v_max. When the piece is too short to change between the two speeds, the faster
  /// end is slowed to the reachable speed and the time that costs on the neighbouring arc
  /// is approximated by the braking time.
  double pieceTime(double length, double entry, double exit) const {
    return pieceTime(length, entry, exit, v_max_);
  }

  /// The same under a speed `limit` (at most v_max; entry and exit at most it).
  double pieceTime(double length, double entry, double exit, double limit) const {
    length = std::max(0.0, length);
    double penalty = 0.0;
    const double reachable_high = reachableSpeed(std::min(entry, exit), length);
    if (std::max(entry, exit) > reachable_high) {
      penalty = (std::max(entry, exit) - reachable_high) / a_max_;
      if (entry > exit) {
        entry = reachable_high;
      } else {
        exit = reachable_high;
      }
    }
    const double peak = peakSpeed(entry, exit, length, limit);
    if (peak <= 0.0) return penalty;
    const double accelerating = std::max(0.0, changeDistance(entry, peak));
    const double braking = std::max(0.0, changeDistance(exit, peak));
    const double cruising = std::max(0.0, length - accelerating - braking);
    return penalty + (peak - entry) / a_max_ + (peak - exit) / a_max_ + cruising / peak;
  }

  double vMax() const { return v_max_; }
  double aMax() const { return a_max_; }

 private:
  double v_max_;
  double a_max_;
};

}  // namespace kinematic_coverage::core
