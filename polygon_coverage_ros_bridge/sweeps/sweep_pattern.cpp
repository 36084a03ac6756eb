#include "polygon_coverage_ros_bridge/sweeps/sweep_pattern.h"

#include <algorithm>
#include <cmath>

#include "polygon_coverage_ros_bridge/decomposition/sweep_direction.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// Lanes are kept this far (relative to the map's scale) inside the cell's extreme
/// positions, so that a lane never degenerates onto a side parallel to it.
constexpr double kRelativeLaneInset = 1e-9;
/// A lane within this (relative) distance of an existing one is the same lane.
constexpr double kRelativeLaneMerge = 1e-6;

/// The interval [lo, hi] of the vertical line at x inside a ring (sweep frame). Edges
/// within `tolerance` of x count as crossing it, so that a lane placed through a corner
/// reaches the corner even when rounding puts it a hair beside the corner's edges.
std::pair<double, double> verticalInterval(const Ring& ring, double x, double tolerance) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const Point2& a = ring[i];
    const Point2& b = ring[(i + 1) % n];
    const double x_lo = std::min(a.x(), b.x());
    const double x_hi = std::max(a.x(), b.x());
    if (x < x_lo - tolerance || x > x_hi + tolerance) continue;
    if (x_hi - x_lo <= tolerance) {
      lo = std::min({lo, a.y(), b.y()});
      hi = std::max({hi, a.y(), b.y()});
      continue;
    }
    const double t = std::clamp((x - a.x()) / (b.x() - a.x()), 0.0, 1.0);
    const double y = a.y() + t * (b.y() - a.y());
    lo = std::min(lo, y);
    hi = std::max(hi, y);
  }
  return {lo, hi};
}

}  // namespace

SweepPatternGenerator::SweepPatternGenerator(const FrustumSensor& sensor, double lane_end_inset,
                                             const PolygonWithHoles& area)
    : sensor_(sensor), lane_end_inset_(lane_end_inset) {
  double scale = 1.0;
  auto collect = [&](const Ring& ring) {
    for (const Point2& p : ring) {
      area_vertices_.push_back(p);
      scale = std::max(scale, p.cwiseAbs().maxCoeff());
    }
  };
  collect(area.hull);
  for (const Ring& hole : area.holes) collect(hole);
  std::sort(area_vertices_.begin(), area_vertices_.end(),
            [](const Point2& a, const Point2& b) { return a.x() < b.x(); });
  vertex_tolerance_ = kRelativeLaneMerge * scale;
}

bool SweepPatternGenerator::isAreaVertex(const Point2& corner) const {
  if (area_vertices_.empty()) return true;
  auto it =
      std::lower_bound(area_vertices_.begin(), area_vertices_.end(), corner.x() - vertex_tolerance_,
                       [](const Point2& vertex, double x) { return vertex.x() < x; });
  for (; it != area_vertices_.end() && it->x() <= corner.x() + vertex_tolerance_; ++it) {
    if ((*it - corner).norm() <= vertex_tolerance_) return true;
  }
  return false;
}

double SweepPatternGenerator::laneEndInset(const FrustumSensor& sensor, double wall_distance) {
  return std::max(0.0, 0.5 * sensor.length() - wall_distance);
}

std::vector<std::pair<Point2, Point2>> SweepPatternGenerator::lanes(const Ring& cell,
                                                                    double direction) const {
  Ring frame;
  double scale = 1.0;
  for (const Point2& p : cell) {
    frame.push_back(toSweepFrame(p, direction));
    scale = std::max(scale, p.cwiseAbs().maxCoeff());
  }
  double x_min = std::numeric_limits<double>::infinity();
  double x_max = -x_min;
  for (const Point2& p : frame) {
    x_min = std::min(x_min, p.x());
    x_max = std::max(x_max, p.x());
  }
  const double inset = kRelativeLaneInset * scale;
  const double spacing = sensor_.sweepDistance();
  const double half_width = 0.5 * sensor_.width();
  const double half_length = 0.5 * sensor_.length();
  const double margin = std::max(inset, std::min(0.5 * spacing, half_width - half_length));

  // The fewest lanes whose outer margins stay within `margin` and whose spacing stays
  // within the sweep distance. The outer lanes go out to the margin, which shortens the
  // joins between lanes, unless that crowds neighbours closer than half a sweep
  // distance (no room to turn between them); then they are spread evenly.
  const double extent = x_max - x_min;
  const int lane_count =
      extent <= 2.0 * margin
          ? 1
          : 1 + std::max(1, static_cast<int>(std::ceil((extent - 2.0 * margin) / spacing - 1e-9)));
  const bool crowded = lane_count > 1 && (extent - 2.0 * margin) / (lane_count - 1) < 0.5 * spacing;
  const double lane_margin = crowded ? std::min(margin, 0.5 * extent / lane_count) : margin;
  std::vector<double> positions;
  if (lane_count == 1) {
    positions.push_back(0.5 * (x_min + x_max));
  } else {
    const double span = extent - 2.0 * lane_margin;
    for (int k = 0; k < lane_count; ++k) {
      positions.push_back(x_min + lane_margin + span * k / (lane_count - 1));
    }
  }

  auto intervals = [&]() {
    std::vector<std::pair<double, double>> result;
    for (double x : positions) result.push_back(verticalInterval(frame, x, inset));
    return result;
  };
  // Corners that no lane's swept footprint reaches get a lane through them: the nearest
  // lane moves there when it can without breaking the placement's rules (neighbours at
  // most one sweep distance apart, outer lanes within the margin of the cell's sides),
  // otherwise an extra lane is added. Moving beats adding: an extra lane beside a lane a
  // few centimetres away makes a pattern that doubles back on itself and a jog no
  // turning radius can smooth (issue 4). A moved lane stays where it was moved.
  std::vector<std::pair<double, double>> spans = intervals();
  std::vector<bool> pinned(positions.size(), false);
  auto movable = [&](std::size_t k, double x) {
    if (pinned[k]) return false;
    const double below = k == 0 ? x_min : positions[k - 1];
    const double above = k + 1 == positions.size() ? x_max : positions[k + 1];
    const double limit_below = k == 0 ? margin : spacing;
    const double limit_above = k + 1 == positions.size() ? margin : spacing;
    return x - below <= limit_below && above - x <= limit_above && x >= below && x <= above;
  };
  // A move can uncover a corner checked before, so the corners are checked again until
  // all are seen; each change leaves one more corner on a lane that never moves again.
  bool changed = true;
  while (changed) {
    changed = false;
    for (std::size_t i = 0; i < frame.size(); ++i) {
      const Point2& corner = frame[i];
      if (!isAreaVertex(cell[i])) continue;
      bool seen = false;
      for (std::size_t k = 0; k < positions.size() && !seen; ++k) {
        seen = std::abs(corner.x() - positions[k]) <= half_width &&
               corner.y() >= spans[k].first - half_length &&
               corner.y() <= spans[k].second + half_length;
      }
      if (seen) continue;
      const double x = std::clamp(corner.x(), x_min + inset, x_max - inset);
      const auto nearest =
          std::min_element(positions.begin(), positions.end(),
                           [&](double a, double b) { return std::abs(a - x) < std::abs(b - x); });
      const std::size_t k = static_cast<std::size_t>(nearest - positions.begin());
      if (std::abs(positions[k] - x) <= kRelativeLaneMerge * scale) continue;
      if (movable(k, x)) {
        positions[k] = x;
        pinned[k] = true;
      } else {
        const auto at = std::upper_bound(positions.begin(), positions.end(), x);
        pinned.insert(pinned.begin() + (at - positions.begin()), true);
        positions.insert(at, x);
      }
      spans = intervals();
      changed = true;
    }
  }

  // Lane ends pulled in by the inset, never past the lane's middle. The corner check
  // above uses the full lanes: the inset only gives up what the footprint's onward
  // half-length still sees.
  std::vector<std::pair<Point2, Point2>> result;
  for (std::size_t k = 0; k < positions.size(); ++k) {
    const auto [lo, hi] = spans[k];
    const double inset = std::min(lane_end_inset_, 0.5 * (hi - lo));
    result.emplace_back(fromSweepFrame({positions[k], lo + inset}, direction),
                        fromSweepFrame({positions[k], hi - inset}, direction));
  }
  return result;
}

std::vector<SweepPattern> SweepPatternGenerator::patterns(const Ring& cell, double direction,
                                                          const TransitionPath& transition) const {
  const auto cell_lanes = lanes(cell, direction);
  const PolygonWithHoles cell_area{cell, {}};
  std::vector<SweepPattern> result;
  for (bool reverse_order : {false, true}) {
    for (bool first_up : {true, false}) {
      SweepPattern pattern;
      pattern.direction = direction;
      bool up = first_up;
      for (std::size_t i = 0; i < cell_lanes.size(); ++i) {
        const auto& lane = cell_lanes[reverse_order ? cell_lanes.size() - 1 - i : i];
        const Point2& from = up ? lane.first : lane.second;
        const Point2& to = up ? lane.second : lane.first;
        if (!pattern.path.empty() && !segmentInside(cell_area, pattern.path.back(), from)) {
          const std::vector<Point2> join = transition(pattern.path.back(), from);
          if (join.size() > 2)
            pattern.path.insert(pattern.path.end(), join.begin() + 1, join.end() - 1);
        }
        pattern.path.push_back(from);
        pattern.path.push_back(to);
        up = !up;
      }
      result.push_back(std::move(pattern));
    }
  }
  return result;
}

}  // namespace kinematic_coverage::core
