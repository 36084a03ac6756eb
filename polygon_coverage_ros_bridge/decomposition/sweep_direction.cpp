#include "polygon_coverage_ros_bridge/decomposition/sweep_direction.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace kinematic_coverage::core {

Point2 directionVector(double direction) { return {std::cos(direction), std::sin(direction)}; }

Point2 toSweepFrame(const Point2& p, double direction) {
  // Rotation by (pi/2 - direction): the direction maps onto +y.
  const double c = std::sin(direction);
  const double s = std::cos(direction);
  return {c * p.x() - s * p.y(), s * p.x() + c * p.y()};
}

Point2 fromSweepFrame(const Point2& p, double direction) {
  const double c = std::sin(direction);
  const double s = std::cos(direction);
  return {c * p.x() + s * p.y(), -s * p.x() + c * p.y()};
}

double altitude(const Ring& ring, double direction) {
  const Point2 normal(-std::sin(direction), std::cos(direction));
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const Point2& p : ring) {
    const double t = normal.dot(p);
    lo = std::min(lo, t);
    hi = std::max(hi, t);
  }
  return ring.empty() ? 0.0 : hi - lo;
}

bool isMonotone(const Ring& ring, double direction) {
  // In the sweep frame lanes are vertical: the ring must be x-monotone, i.e. its
  // x-coordinates rise once and fall once around the boundary. Steps shorter than a
  // tolerance relative to the ring's size are ignored. The count of sign changes only
  // grows, so a third change ends the walk (most directions of a noisy cell fail early).
  const std::size_t n = ring.size();
  if (n < 3) return false;
  double scale = 0.0;
  for (const Point2& p : ring) scale = std::max(scale, p.cwiseAbs().maxCoeff());
  const double tolerance = 1e-9 * std::max(1.0, scale);
  const double c = std::sin(direction);
  const double s = std::cos(direction);
  const auto sweepX = [&](const Point2& p) { return c * p.x() - s * p.y(); };
  int changes = 0;
  int previous_sign = 0;
  int first_sign = 0;
  double x = sweepX(ring[0]);
  for (std::size_t i = 0; i < n && changes <= 2; ++i) {
    const double next_x = sweepX(ring[(i + 1) % n]);
    const double dx = next_x - x;
    x = next_x;
    if (std::abs(dx) <= tolerance) continue;
    const int sign = dx > 0 ? 1 : -1;
    if (first_sign == 0) first_sign = sign;
    if (previous_sign != 0 && sign != previous_sign) ++changes;
    previous_sign = sign;
  }
  if (previous_sign != 0 && previous_sign != first_sign) ++changes;
  return changes <= 2;
}

std::vector<double> candidateDirections(const std::vector<Ring>& rings, std::size_t max_count) {
  std::vector<std::pair<double, double>> directions;  // (angle in [0, pi), total length)
  for (const Ring& ring : rings) {
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      const Point2 edge = ring[(i + 1) % n] - ring[i];
      const double length = edge.norm();
      if (length <= 0.0) continue;
      double angle = std::atan2(edge.y(), edge.x());
      if (angle < 0.0) angle += M_PI;
      if (angle >= M_PI) angle -= M_PI;
      directions.emplace_back(angle, length);
    }
  }
  std::sort(directions.begin(), directions.end());
  std::vector<std::pair<double, double>> merged;  // (total length, first angle of the group)
  for (const auto& [angle, length] : directions) {
    if (!merged.empty() && angle - merged.back().second <= kDirectionTolerance) {
      merged.back().first += length;
      continue;
    }
    merged.emplace_back(length, angle);
  }
  // Wrap-around: directions near pi and near 0 are the same.
  if (merged.size() > 1 &&
      merged.back().second + kDirectionTolerance >= M_PI + merged.front().second) {
    merged.front().first += merged.back().first;
    merged.pop_back();
  }
  std::stable_sort(merged.begin(), merged.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  if (merged.size() > max_count) merged.resize(max_count);
  std::vector<double> result;
  for (const auto& entry : merged) result.push_back(entry.second);
  return result;
}

}  // namespace kinematic_coverage::core
