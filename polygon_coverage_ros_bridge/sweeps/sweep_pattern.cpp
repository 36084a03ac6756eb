#include "polygon_coverage_ros_bridge/sweeps/sweep_pattern.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "polygon_coverage_ros_bridge/decomposition/sweep_direction.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// Lanes are kept this far (relative to the map's scale) inside the cell's extreme
/// positions, so that a lane never degenerates onto a side parallel to it.
constexpr double kRelativeLaneInset = 1e-9;
/// A lane within this (relative) distance of an existing one is the same lane.
constexpr double kRelativeLaneMerge = 1e-6;
/// Sides within this angle (radians, 15 degrees) of the lanes' direction are flanks: every
/// point of a flank that lies alongside a lane must lie in a lane's footprint (soak seed 3640).
/// Where the lanes are not parallel to such a side, it leaves a wedge between the ends of
/// two neighbouring lanes that runs along the lanes for up to (s - W/2) / tan(angle) - L/2:
/// most of a lane's length when the side is nearly parallel to them (soak seed 3640: 2
/// degrees, 29 m). Steeper sides are where lanes end: their wedges are short, the joins
/// between lane ends run along them, and seeing them too would cost lanes (45 degrees:
/// +3.0 % mean time cost over soak seeds 0-199 for +0.0008 % coverage; 15 degrees: +0.3 %).
constexpr double kMaxFlankAngle = 0.2618;
/// Lane ends this close (relative to the map's scale) to the area's boundary are put on it:
/// ten times the decomposition's rounding of the cells' corners.
constexpr double kRelativeBoundarySnap = 1e-8;
/// Moves and extra lanes allowed per vertex and initial lane of a cell (a bound that
/// only guards against endless rounding; each change sees more of the cell).
constexpr int kChangesPerVertex = 4;

/// An interval [first, second] of a coordinate or a parameter.
using Interval = std::pair<double, double>;

/// The interval [lo, hi] of the vertical line at x inside a ring (sweep frame). Edges
/// within `tolerance` of x count as crossing it, so that a lane placed through a corner
/// reaches the corner even when rounding puts it a hair beside the corner's edges.
Interval verticalInterval(const Ring& ring, double x, double tolerance) {
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

/// Sorted, with overlapping intervals joined.
std::vector<Interval> merged(std::vector<Interval> intervals) {
  std::sort(intervals.begin(), intervals.end());
  std::vector<Interval> result;
  for (const Interval& interval : intervals) {
    if (!result.empty() && interval.first <= result.back().second) {
      result.back().second = std::max(result.back().second, interval.second);
    } else {
      result.push_back(interval);
    }
  }
  return result;
}

/// The parts of the merged intervals `keep` outside the merged intervals `remove`.
std::vector<Interval> subtracted(const std::vector<Interval>& keep,
                                 const std::vector<Interval>& remove) {
  std::vector<Interval> result;
  for (const auto& [lo, hi] : keep) {
    double cursor = lo;
    for (const auto& [remove_lo, remove_hi] : remove) {
      if (remove_hi <= cursor || remove_lo >= hi) continue;
      if (remove_lo > cursor) result.emplace_back(cursor, remove_lo);
      cursor = std::max(cursor, remove_hi);
    }
    if (cursor < hi) result.emplace_back(cursor, hi);
  }
  return result;
}

/// The parameters t in [0, 1] of the points a + t (b - a) within `reach` of the segment
/// [c, d]: the line's intersection with the capsule around the segment, which is convex,
/// so the hull of its intersections with the two end discs and the band between them.
/// Empty (first > second) when no point is that close.
Interval withinReach(const Point2& a, const Point2& b, const Point2& c, const Point2& d,
                     double reach) {
  const Point2 u = b - a;
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  auto include = [&](double t0, double t1) {
    if (t0 > t1) return;
    lo = std::min(lo, t0);
    hi = std::max(hi, t1);
  };
  for (const Point2& centre : {c, d}) {
    const Point2 w = a - centre;
    const double qa = u.squaredNorm();
    const double qb = 2.0 * w.dot(u);
    const double qc = w.squaredNorm() - reach * reach;
    const double discriminant = qb * qb - 4.0 * qa * qc;
    if (qa == 0.0 || discriminant < 0.0) continue;
    const double root = std::sqrt(discriminant);
    include((-qb - root) / (2.0 * qa), (-qb + root) / (2.0 * qa));
  }
  const Point2 v = d - c;
  const double length = v.norm();
  if (length > 0.0) {
    const Point2 along = v / length;
    const Point2 normal(-along.y(), along.x());
    double t0 = -std::numeric_limits<double>::infinity();
    double t1 = -t0;
    // Keeps the t where value0 + slope * t lies in [min, max].
    auto clip = [&](double value0, double slope, double min, double max) {
      if (slope == 0.0) {
        if (value0 < min || value0 > max) t0 = t1 + 1.0;
        return;
      }
      const double ta = (min - value0) / slope;
      const double tb = (max - value0) / slope;
      t0 = std::max(t0, std::min(ta, tb));
      t1 = std::min(t1, std::max(ta, tb));
    };
    clip((a - c).dot(along), u.dot(along), 0.0, length);
    clip((a - c).dot(normal), u.dot(normal), -reach, reach);
    include(t0, t1);
  }
  return {std::max(lo, 0.0), std::min(hi, 1.0)};
}

/// The parts of a cell's flanks that lie alongside a lane but in no lane's swept footprint.
struct FlankGap {
  double length = 0.0;           ///< their total length
  Point2 from = Point2::Zero();  ///< the ends of the first of them (sweep frame)
  Point2 to = Point2::Zero();
};

/// Measures the FlankGap of lanes at `positions` (sweep frame, increasing) whose vertical
/// extents in the cell are `spans`. A point of a flank counts when it lies alongside one
/// of its two neighbouring lanes (within that lane's extent) but no footprint swept along
/// a lane sees it (W/2 across, L/2 beyond the lane's ends). Each flank is split where the
/// lanes seeing it or its neighbours change (at x_k and x_k +- W/2); along each piece the
/// flank is straight and both sets are fixed, so the unseen part is exact. Unseen parts
/// no longer than `tolerance` are rounding and left out.
FlankGap flankGap(const std::vector<std::pair<Point2, Point2>>& flanks,
                  const std::vector<double>& positions, const std::vector<Interval>& spans,
                  double half_width, double half_length, double tolerance) {
  FlankGap gap;
  for (const auto& [p, q] : flanks) {
    const Point2 delta = q - p;
    const double length = delta.norm();
    if (length == 0.0) continue;
    std::vector<double> breaks = {0.0, 1.0};
    if (delta.x() != 0.0) {
      for (double x : positions) {
        for (double edge : {x - half_width, x, x + half_width}) {
          const double t = (edge - p.x()) / delta.x();
          if (t > 0.0 && t < 1.0) breaks.push_back(t);
        }
      }
    }
    std::sort(breaks.begin(), breaks.end());
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
      const double t0 = breaks[i];
      const double t1 = breaks[i + 1];
      if (t1 <= t0) continue;
      const double x = p.x() + 0.5 * (t0 + t1) * delta.x();
      const auto right = std::lower_bound(positions.begin(), positions.end(), x);
      std::vector<Interval> alongside;
      if (right != positions.end()) alongside.push_back(spans[right - positions.begin()]);
      if (right != positions.begin()) alongside.push_back(spans[right - positions.begin() - 1]);
      std::vector<Interval> seen;
      const auto first = std::lower_bound(positions.begin(), positions.end(), x - half_width);
      const auto last = std::upper_bound(positions.begin(), positions.end(), x + half_width);
      for (auto it = first; it != last; ++it) {
        const Interval& span = spans[it - positions.begin()];
        seen.emplace_back(span.first - half_length, span.second + half_length);
      }
      const double y0 = p.y() + t0 * delta.y();
      const double y1 = p.y() + t1 * delta.y();
      for (const auto& [lo, hi] : subtracted(merged(alongside), merged(seen))) {
        double ta = t0;
        double tb = t1;
        if (delta.y() != 0.0) {
          const double unseen_lo = std::max(lo, std::min(y0, y1));
          const double unseen_hi = std::min(hi, std::max(y0, y1));
          if (unseen_lo >= unseen_hi) continue;
          ta = (unseen_lo - p.y()) / delta.y();
          tb = (unseen_hi - p.y()) / delta.y();
        } else if (!(lo < y0 && y0 < hi)) {
          continue;
        }
        const double unseen_length = std::abs(tb - ta) * length;
        if (unseen_length <= tolerance) continue;
        if (gap.length == 0.0) {
          gap.from = p + std::min(ta, tb) * delta;
          gap.to = p + std::max(ta, tb) * delta;
        }
        gap.length += unseen_length;
      }
    }
  }
  return gap;
}

/// Where lanes cross a cell (sweep frame: lanes vertical, at increasing x), and the moves
/// and extra lanes that make every corner of the area and every flank seen while keeping
/// the placement's rules: neighbours at most one sweep distance apart, outer lanes within
/// the margin of the cell's sides.
class LanePlacement {
 public:
  /// The limits of a placement in `frame` (the cell in the sweep frame).
  struct Limits {
    double x_min;
    double x_max;
    double inset;  ///< how far inside the cell a lane stays
    double margin;
    double spacing;
    double half_width;
    double half_length;
    double tolerance;
  };

  LanePlacement(const Ring& frame, std::vector<double> positions, const Limits& limits,
                std::vector<std::pair<Point2, Point2>> flanks)
      : frame_(frame),
        limits_(limits),
        flanks_(std::move(flanks)),
        positions_(std::move(positions)),
        pinned_(positions_.size(), false) {
    refresh();
  }

  /// Corners that no lane's swept footprint reaches get a lane through them: the nearest
  /// lane moves there when it can without breaking the placement's rules and without
  /// leaving more of the flanks unseen, otherwise an extra lane is added. Moving beats
  /// adding: an extra lane beside a lane a few centimetres away makes a pattern that
  /// doubles back on itself and a jog no turning radius can smooth. A moved lane stays
  /// where it was moved.
  ///
  /// A move can uncover a corner or a flank checked before, so both are checked again until
  /// all are seen; each change leaves one more corner or flank point on a lane that never
  /// moves again. A flank found unseen gets the move or the extra lane (through one end of
  /// its first unseen part, or half a footprint width beside it) that leaves the least of
  /// the flanks unseen; a move wins a tie. Every change makes the unseen part shorter or
  /// sees one more corner; the bound on changes only guards against endless rounding.
  /// `area_corner[i]`: frame vertex i is a corner of the area, which must be seen.
  void seeCornersAndFlanks(const std::vector<bool>& area_corner) {
    int changes_left = kChangesPerVertex * static_cast<int>(frame_.size() + positions_.size());
    bool changed = true;
    while (changed && changes_left > 0) {
      const int corner_changes = seeCorners(area_corner);
      changes_left -= corner_changes;
      changed = corner_changes > 0;
      if (changed || gap_.length <= limits_.tolerance) continue;
      if (!seeFlank()) break;
      changed = true;
      --changes_left;
    }
  }

  const std::vector<double>& positions() const { return positions_; }
  /// The lanes' vertical extents in the cell.
  const std::vector<Interval>& spans() const { return spans_; }

 private:
  std::vector<Interval> intervalsAt(const std::vector<double>& xs) const {
    std::vector<Interval> result;
    for (double x : xs) result.push_back(verticalInterval(frame_, x, limits_.inset));
    return result;
  }
  FlankGap flankGapAt(const std::vector<double>& xs) const {
    return flankGap(flanks_, xs, intervalsAt(xs), limits_.half_width, limits_.half_length,
                    limits_.tolerance);
  }
  void refresh() {
    spans_ = intervalsAt(positions_);
    gap_ = flankGapAt(positions_);
  }
  bool movable(std::size_t k, double x) const {
    if (pinned_[k]) return false;
    const double below = k == 0 ? limits_.x_min : positions_[k - 1];
    const double above = k + 1 == positions_.size() ? limits_.x_max : positions_[k + 1];
    const double limit_below = k == 0 ? limits_.margin : limits_.spacing;
    const double limit_above = k + 1 == positions_.size() ? limits_.margin : limits_.spacing;
    return x - below <= limit_below && above - x <= limit_above && x >= below && x <= above;
  }
  std::size_t nearestLane(double x) const {
    const auto nearest =
        std::min_element(positions_.begin(), positions_.end(),
                         [&](double a, double b) { return std::abs(a - x) < std::abs(b - x); });
    return static_cast<std::size_t>(nearest - positions_.begin());
  }
  std::vector<double> moved(std::size_t k, double x) const {
    std::vector<double> result = positions_;
    result[k] = x;
    return result;
  }
  std::vector<double> added(double x) const {
    std::vector<double> result = positions_;
    result.insert(std::upper_bound(result.begin(), result.end(), x), x);
    return result;
  }
  void move(std::size_t k, double x) {
    positions_[k] = x;
    pinned_[k] = true;
  }
  void add(double x) {
    const auto at = std::upper_bound(positions_.begin(), positions_.end(), x);
    pinned_.insert(pinned_.begin() + (at - positions_.begin()), true);
    positions_.insert(at, x);
  }
  double clamped(double x) const {
    return std::clamp(x, limits_.x_min + limits_.inset, limits_.x_max - limits_.inset);
  }

  /// One pass over the area's corners, moving or adding a lane for each unseen one;
  /// returns the number of changes.
  int seeCorners(const std::vector<bool>& area_corner) {
    int changes = 0;
    for (std::size_t i = 0; i < frame_.size(); ++i) {
      const Point2& corner = frame_[i];
      if (!area_corner[i]) continue;
      bool seen = false;
      for (std::size_t k = 0; k < positions_.size() && !seen; ++k) {
        seen = std::abs(corner.x() - positions_[k]) <= limits_.half_width &&
               corner.y() >= spans_[k].first - limits_.half_length &&
               corner.y() <= spans_[k].second + limits_.half_length;
      }
      if (seen) continue;
      const double x = clamped(corner.x());
      const std::size_t k = nearestLane(x);
      if (std::abs(positions_[k] - x) <= limits_.tolerance) continue;
      if (movable(k, x) && flankGapAt(moved(k, x)).length <= gap_.length + limits_.tolerance) {
        move(k, x);
      } else {
        add(x);
      }
      refresh();
      ++changes;
    }
    return changes;
  }

  /// The move or extra lane that leaves the least of the flanks unseen, if it leaves less
  /// than now; false when none does.
  bool seeFlank() {
    double best_move = std::numeric_limits<double>::infinity();
    double best_add = best_move;
    std::size_t move_lane = 0;
    double move_x = 0.0;
    double add_x = 0.0;
    for (double end : {gap_.from.x(), gap_.to.x()}) {
      for (double offset : {0.0, -limits_.half_width, limits_.half_width}) {
        const double x = clamped(end + offset);
        const std::size_t k = nearestLane(x);
        if (std::abs(positions_[k] - x) <= limits_.tolerance) continue;
        const double left_by_move = movable(k, x) ? flankGapAt(moved(k, x)).length
                                                  : std::numeric_limits<double>::infinity();
        if (left_by_move < best_move) {
          best_move = left_by_move;
          move_lane = k;
          move_x = x;
        }
        const double left_by_add = flankGapAt(added(x)).length;
        if (left_by_add < best_add) {
          best_add = left_by_add;
          add_x = x;
        }
      }
    }
    if (std::min(best_move, best_add) >= gap_.length - limits_.tolerance) return false;
    if (best_move <= best_add + limits_.tolerance) {
      move(move_lane, move_x);
    } else {
      add(add_x);
    }
    refresh();
    return true;
  }

  const Ring& frame_;
  const Limits limits_;
  const std::vector<std::pair<Point2, Point2>> flanks_;
  std::vector<double> positions_;
  std::vector<bool> pinned_;
  std::vector<Interval> spans_;
  FlankGap gap_;
};

/// The fewest lanes across [x_min, x_max] whose outer margins stay within `margin` and
/// whose spacing stays within `spacing`. The outer lanes go out to the margin, which
/// shortens the joins between lanes, unless that crowds neighbours closer than half a
/// sweep distance (no room to turn between them); then they are spread evenly.
std::vector<double> evenLanePositions(double x_min, double x_max, double margin, double spacing) {
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
  return positions;
}

/// Edges, each from its end with the smaller x, sorted by that x.
using EdgesByX = std::vector<std::pair<Point2, Point2>>;

/// The edges of every ring of the area as EdgesByX; `widest` is set to the largest x extent
/// of an edge.
EdgesByX edgesByX(const PolygonWithHoles& area, double* widest) {
  EdgesByX edges;
  *widest = 0.0;
  auto collect = [&](const Ring& ring) {
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      const Point2& p = ring[i];
      const Point2& q = ring[(i + 1) % n];
      edges.push_back(p.x() <= q.x() ? std::make_pair(p, q) : std::make_pair(q, p));
      *widest = std::max(*widest, std::abs(q.x() - p.x()));
    }
  };
  collect(area.hull);
  for (const Ring& hole : area.holes) collect(hole);
  std::sort(edges.begin(), edges.end(),
            [](const auto& a, const auto& b) { return a.first.x() < b.first.x(); });
  return edges;
}

/// Calls visit(edge) for the edges whose x extent meets [x_lo, x_hi].
template <typename Visit>
void visitEdgesOver(const EdgesByX& edges, double widest, double x_lo, double x_hi, Visit&& visit) {
  auto it = std::lower_bound(edges.begin(), edges.end(), x_lo - widest,
                             [](const auto& edge, double x) { return edge.first.x() < x; });
  for (; it != edges.end() && it->first.x() <= x_hi; ++it) {
    if (it->second.x() >= x_lo) visit(*it);
  }
}

/// The nearest point of the edges when one lies within `reach` of p, else p.
Point2 nearestOnEdges(const EdgesByX& edges, double widest, const Point2& p, double reach) {
  Point2 nearest = p;
  double nearest_distance = reach;
  visitEdgesOver(edges, widest, p.x() - reach, p.x() + reach, [&](const auto& edge) {
    const Point2 candidate = closestPointOnSegment(p, edge.first, edge.second);
    const double distance = (candidate - p).norm();
    if (distance <= nearest_distance) nearest_distance = distance, nearest = candidate;
  });
  return nearest;
}

/// True when an edge passes within `reach` of p.
bool nearEdges(const EdgesByX& edges, double widest, const Point2& p, double reach) {
  bool near = false;
  visitEdgesOver(edges, widest, p.x() - reach, p.x() + reach, [&](const auto& edge) {
    near = near || (closestPointOnSegment(p, edge.first, edge.second) - p).norm() <= reach;
  });
  return near;
}

}  // namespace

SweepPatternGenerator::SweepPatternGenerator(const FrustumSensor& sensor, double lane_end_inset,
                                             const PolygonWithHoles& area)
    : sensor_(sensor), lane_end_inset_(lane_end_inset) {
  area_edges_ = edgesByX(area, &widest_area_edge_);
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

SweepPatternGenerator::SweepPatternGenerator(const FrustumSensor& sensor, double lane_end_inset,
                                             const PolygonWithHoles& area,
                                             const PolygonWithHoles& exact_area)
    : SweepPatternGenerator(sensor, lane_end_inset, area) {
  double widest_exact_edge = 0.0;
  EdgesByX exact_edges = edgesByX(exact_area, &widest_exact_edge);
  if (exact_edges.size() == area_edges_.size()) return;  // every vertex kept: exact
  exact_edges_ = std::move(exact_edges);
  widest_exact_edge_ = widest_exact_edge;
}

Point2 SweepPatternGenerator::onNearbyAreaBoundary(const Point2& p, double reach) const {
  return nearestOnEdges(area_edges_, widest_area_edge_, p, reach);
}

double SweepPatternGenerator::extensionToExactBoundary(const Point2& end, const Point2& along,
                                                       double snap) const {
  if (exact_edges_.empty()) return 0.0;
  const double reach = sensor_.sweepDistance();
  const Point2 far = end + reach * along;
  double nearest = reach;
  visitEdgesOver(exact_edges_, widest_exact_edge_, std::min(end.x(), far.x()) - snap,
                 std::max(end.x(), far.x()) + snap, [&](const auto& edge) {
                   const auto& [c, d] = edge;
                   if ((closestPointOnSegment(end, c, d) - end).norm() <= snap) {
                     nearest = 0.0;
                     return;
                   }
                   const Point2 v = d - c;
                   const double denominator = cross({0, 0}, along, v);
                   if (denominator == 0.0) return;
                   const double t = cross({0, 0}, c - end, v) / denominator;
                   const double u = cross({0, 0}, c - end, along) / denominator;
                   if (t >= 0.0 && u >= 0.0 && u <= 1.0) nearest = std::min(nearest, t);
                 });
  return nearest;
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

std::vector<std::pair<double, double>> SweepPatternGenerator::onAreaBoundary(
    const Point2& a, const Point2& b) const {
  const Point2 delta = b - a;
  const double length_squared = delta.squaredNorm();
  std::vector<Interval> parts;
  if (length_squared == 0.0) return parts;
  const double length = std::sqrt(length_squared);
  const double x_lo = std::min(a.x(), b.x()) - vertex_tolerance_;
  const double x_hi = std::max(a.x(), b.x()) + vertex_tolerance_;
  auto it = std::lower_bound(area_edges_.begin(), area_edges_.end(), x_lo - widest_area_edge_,
                             [](const auto& edge, double x) { return edge.first.x() < x; });
  for (; it != area_edges_.end() && it->first.x() <= x_hi; ++it) {
    const auto& [c, d] = *it;
    if (d.x() < x_lo) continue;
    if (std::abs(cross(a, b, c)) > vertex_tolerance_ * length ||
        std::abs(cross(a, b, d)) > vertex_tolerance_ * length) {
      continue;
    }
    const double tc = (c - a).dot(delta) / length_squared;
    const double td = (d - a).dot(delta) / length_squared;
    const double lo = std::max(0.0, std::min(tc, td));
    const double hi = std::min(1.0, std::max(tc, td));
    if (lo < hi) parts.emplace_back(lo, hi);
  }
  return merged(parts);
}

std::vector<std::pair<Point2, Point2>> SweepPatternGenerator::sidesToSee(const Ring& cell,
                                                                         double cut_reach) const {
  const std::vector<Interval> whole = {{0.0, 1.0}};
  std::vector<std::vector<Interval>> side_parts;
  std::vector<std::pair<Point2, Point2>> cuts;
  for (std::size_t i = 0, n = cell.size(); i < n; ++i) {
    const Point2& a = cell[i];
    const Point2& b = cell[(i + 1) % n];
    side_parts.push_back(area_vertices_.empty() ? whole : onAreaBoundary(a, b));
    for (const auto& [lo, hi] : subtracted(whole, side_parts.back())) {
      cuts.emplace_back(a + lo * (b - a), a + hi * (b - a));
    }
  }
  std::vector<std::pair<Point2, Point2>> sides;
  for (std::size_t i = 0, n = cell.size(); i < n; ++i) {
    const Point2& a = cell[i];
    const Point2& b = cell[(i + 1) % n];
    std::vector<Interval> near_cuts;
    for (const auto& [c, d] : cuts) near_cuts.push_back(withinReach(a, b, c, d, cut_reach));
    near_cuts.erase(std::remove_if(near_cuts.begin(), near_cuts.end(),
                                   [](const Interval& t) { return t.first >= t.second; }),
                    near_cuts.end());
    for (const auto& [lo, hi] : subtracted(side_parts[i], merged(near_cuts))) {
      sides.emplace_back(a + lo * (b - a), a + hi * (b - a));
    }
  }
  return sides;
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
  LanePlacement::Limits limits;
  limits.x_min = std::numeric_limits<double>::infinity();
  limits.x_max = -limits.x_min;
  for (const Point2& p : frame) {
    limits.x_min = std::min(limits.x_min, p.x());
    limits.x_max = std::max(limits.x_max, p.x());
  }
  limits.inset = kRelativeLaneInset * scale;
  limits.spacing = sensor_.sweepDistance();
  limits.half_width = 0.5 * sensor_.width();
  limits.half_length = 0.5 * sensor_.length();
  limits.margin = std::max(limits.inset,
                           std::min(0.5 * limits.spacing, limits.half_width - limits.half_length));
  limits.tolerance = kRelativeLaneMerge * scale;

  // The flanks of the lanes that their footprints must see (sweep frame): the parts of the
  // sides within kMaxFlankAngle of the lanes' direction, which the lanes run alongside.
  std::vector<std::pair<Point2, Point2>> flanks;
  const double max_flank_slope = std::tan(kMaxFlankAngle);
  for (const auto& [a, b] : sidesToSee(cell, limits.half_width - limits.margin)) {
    const Point2 from = toSweepFrame(a, direction);
    const Point2 to = toSweepFrame(b, direction);
    if (std::abs(to.x() - from.x()) <= max_flank_slope * std::abs(to.y() - from.y())) {
      flanks.emplace_back(from, to);
    }
  }
  LanePlacement placement(
      frame, evenLanePositions(limits.x_min, limits.x_max, limits.margin, limits.spacing), limits,
      std::move(flanks));
  std::vector<bool> area_corner;
  for (const Point2& corner : cell) area_corner.push_back(isAreaVertex(corner));
  placement.seeCornersAndFlanks(area_corner);
  return laneEnds(cell, direction, placement.positions(), placement.spans(), scale);
}

std::vector<std::pair<Point2, Point2>> SweepPatternGenerator::laneEnds(
    const Ring& cell, double direction, const std::vector<double>& positions,
    const std::vector<std::pair<double, double>>& spans, double scale) const {
  // Lane ends pulled in by the inset, never past the lane's middle. The corner and flank checks
  // (LanePlacement) use the full lanes: the inset only gives up what the footprint's onward half-
  // length still sees. An end that the corner tolerance of verticalInterval put a hair outside the
  // cell (a lane through an acute corner) moves onto the cell's nearest boundary point, so that
  // every lane end lies in the cell and so in the area (planner_fuzzer: a lane end 1e-8 beyond a
  // corner of the offset free area). An end then within kRelativeBoundarySnap of the area's
  // boundary moves onto it: the cells follow the area's boundary only up to the decomposition's
  // rounding, and a route point a hair outside a corner of the area sees nothing (planner_fuzzer:
  // an offset free area 0.55 m across at x = 15 m, whose lane ends lay 1e-9 m beyond its corners).
  auto insideCell = [&](const Point2& end) {
    Point2 nearest = end;
    if (!insideRing(end, cell)) {
      double nearest_distance = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0, n = cell.size(); i < n; ++i) {
        const Point2 candidate = closestPointOnSegment(end, cell[i], cell[(i + 1) % n]);
        const double distance = (candidate - end).norm();
        if (distance < nearest_distance) nearest_distance = distance, nearest = candidate;
      }
    }
    return onNearbyAreaBoundary(nearest, kRelativeBoundarySnap * scale);
  };
  // With a simplified area, an end on its boundary first goes on to the exact boundary
  // (extensionToExactBoundary); an end that then lies beyond the cell moves onto the exact
  // boundary when it is within rounding of it, as above.
  const double boundary_reach = kRelativeLaneMerge * scale;
  const double snap = kRelativeBoundarySnap * scale;
  auto extension = [&](const Point2& end, const Point2& along) {
    if (exact_edges_.empty() || !nearEdges(area_edges_, widest_area_edge_, end, boundary_reach)) {
      return 0.0;
    }
    return extensionToExactBoundary(end, along, boundary_reach);
  };
  auto placed = [&](double x, double y, double beyond_cell) {
    const Point2 end = fromSweepFrame({x, y}, direction);
    if (beyond_cell <= 0.0) return insideCell(end);
    return nearestOnEdges(exact_edges_, widest_exact_edge_, end, snap);
  };
  const Point2 up = fromSweepFrame({0.0, 1.0}, direction) - fromSweepFrame({0.0, 0.0}, direction);
  std::vector<std::pair<Point2, Point2>> result;
  for (std::size_t k = 0; k < positions.size(); ++k) {
    const auto [cell_lo, cell_hi] = spans[k];
    const double below = extension(fromSweepFrame({positions[k], cell_lo}, direction), -up);
    const double above = extension(fromSweepFrame({positions[k], cell_hi}, direction), up);
    const double lo = cell_lo - below;
    const double hi = cell_hi + above;
    const double inset = std::min(lane_end_inset_, 0.5 * (hi - lo));
    result.emplace_back(placed(positions[k], lo + inset, below - inset),
                        placed(positions[k], hi - inset, above - inset));
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
