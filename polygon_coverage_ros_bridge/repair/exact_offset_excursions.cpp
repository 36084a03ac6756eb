#include "polygon_coverage_ros_bridge/repair/exact_offset_excursions.h"

#include <algorithm>
#include <cmath>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// m short of the full length at which an excursion ends, so that rounding leaves its end
/// at the wall distance or beyond, never nearer.
constexpr double kApexMargin = 1e-6;
/// An excursion ends where a step would gain less than this (m), or after this many steps
/// (a bisector that runs along a wall nears it slowly).
constexpr double kTraceTolerance = 1e-4;
constexpr int kTraceSteps = 32;
/// A walk's legs after its first excursion, the directions each tries (the target's and
/// kWalkTurns each side of it, kWalkStep radians apart) and the halvings that find a leg's
/// length. A leg is driven when it comes nearer the target by min_length.
constexpr int kWalkLegs = 6;
constexpr int kWalkTurns = 6;
constexpr double kWalkStep = 0.25;
constexpr int kLegHalvings = 20;

void addWalls(const Ring& ring, std::vector<Point2>* from, std::vector<Point2>* to) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    from->push_back(ring[i]);
    to->push_back(ring[(i + 1) % ring.size()]);
  }
}

/// The distance between the segments ab and cd: 0 where they cross, else the nearest of an
/// end of one to the other.
double distanceBetweenSegments(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const double abc = cross(a, b, c);
  const double abd = cross(a, b, d);
  const double cda = cross(c, d, a);
  const double cdb = cross(c, d, b);
  if (((abc > 0.0 && abd < 0.0) || (abc < 0.0 && abd > 0.0)) &&
      ((cda > 0.0 && cdb < 0.0) || (cda < 0.0 && cdb > 0.0))) {
    return 0.0;
  }
  return std::min({distanceToSegment(a, c, d), distanceToSegment(b, c, d),
                   distanceToSegment(c, a, b), distanceToSegment(d, a, b)});
}

}  // namespace

ExactOffsetExcursions::ExactOffsetExcursions(const PolygonWithHoles& free_area,
                                             double wall_distance, double min_length,
                                             double max_length)
    : wall_distance_(wall_distance), min_length_(min_length), max_length_(max_length) {
  addWalls(free_area.hull, &from_, &to_);
  for (const Ring& hole : free_area.holes) addWalls(hole, &from_, &to_);
  grid_ = EdgeGrid(from_, to_, EdgeGrid::Layout{});
}

double ExactOffsetExcursions::wallDistance(const Point2& p, double reach) const {
  const Point2 box(reach, reach);
  std::vector<int> ids;
  grid_.collect(grid_.cellsOf(p - box, p + box), &ids);
  double nearest = reach;
  for (const int i : ids) nearest = std::min(nearest, distanceToSegment(p, from_[i], to_[i]));
  return nearest;
}

std::optional<Point2> ExactOffsetExcursions::apex(const Point2& before, const Point2& corner,
                                                  const Point2& after) const {
  const Point2 in = corner - before;
  const Point2 out = after - corner;
  if (in.norm() <= kLengthTolerance || out.norm() <= kLengthTolerance) return std::nullopt;
  if (cross(before, corner, after) >= 0.0) return std::nullopt;  // turns toward its inside
  // The inward normals' sum points into the ring's inside; its opposite bisects the outside.
  const Point2 inward =
      Point2(-in.y(), in.x()).normalized() + Point2(-out.y(), out.x()).normalized();
  return toward(corner, -inward);
}

std::optional<Point2> ExactOffsetExcursions::toward(const Point2& from,
                                                    const Point2& direction) const {
  if (!(wall_distance_ > 0.0) || from_.empty() || direction.norm() <= kLengthTolerance) {
    return std::nullopt;
  }
  // Out by steps that each keep the wall distance: from a point d from the walls, d less
  // the wall distance (sphere tracing), until the walls are that near.
  const Point2 outward = direction.normalized();
  const double reach = wall_distance_ + max_length_;
  double length = 0.0;
  for (int step = 0; step < kTraceSteps && length < max_length_; ++step) {
    const double advance =
        wallDistance(from + length * outward, reach) - wall_distance_ - kApexMargin;
    if (advance <= kTraceTolerance) break;
    length = std::min(length + advance, max_length_);
  }
  if (length < min_length_) return std::nullopt;
  return Point2(from + length * outward);
}

bool ExactOffsetExcursions::keepsDistance(const Point2& a, const Point2& b) const {
  if (!(wall_distance_ > 0.0)) return true;
  const Point2 reach(wall_distance_, wall_distance_);
  const Point2 low(std::min(a.x(), b.x()), std::min(a.y(), b.y()));
  const Point2 high(std::max(a.x(), b.x()), std::max(a.y(), b.y()));
  std::vector<int> ids;
  grid_.collect(grid_.cellsOf(low - reach, high + reach), &ids);
  return std::all_of(ids.begin(), ids.end(), [&](int i) {
    return distanceBetweenSegments(a, b, from_[i], to_[i]) >= wall_distance_ - kApexMargin;
  });
}

Point2 ExactOffsetExcursions::farthestKeeping(const Point2& from, const Point2& direction) const {
  if (keepsDistance(from, from + max_length_ * direction)) return from + max_length_ * direction;
  // A shorter segment of a ray keeps the distance where a longer one does.
  double kept = 0.0;
  double broken = max_length_;
  for (int halving = 0; halving < kLegHalvings; ++halving) {
    const double middle = 0.5 * (kept + broken);
    (keepsDistance(from, from + middle * direction) ? kept : broken) = middle;
  }
  return from + kept * direction;
}

std::vector<Point2> ExactOffsetExcursions::walk(const Point2& from, const Point2& target,
                                                double reach) const {
  std::vector<Point2> way;
  if (const std::optional<Point2> first = toward(from, target - from)) way.push_back(*first);
  for (int leg = 0; leg < kWalkLegs; ++leg) {
    const Point2 at = way.empty() ? from : way.back();
    const double remaining = (target - at).norm();
    if (remaining <= reach || remaining <= kLengthTolerance) break;
    const double heading = std::atan2(target.y() - at.y(), target.x() - at.x());
    Point2 best = at;
    double best_remaining = remaining - min_length_;
    for (int turn = -kWalkTurns; turn <= kWalkTurns; ++turn) {
      const double angle = heading + turn * kWalkStep;
      const Point2 end = farthestKeeping(at, Point2(std::cos(angle), std::sin(angle)));
      const double left = (target - end).norm();
      if (left < best_remaining) {
        best = end;
        best_remaining = left;
      }
    }
    if (best == at) break;
    way.push_back(best);
  }
  return way;
}

}  // namespace kinematic_coverage::core
