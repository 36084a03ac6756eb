#include "coverage_system/mission/autopilot_mission.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

#include "polygon_coverage_ros_bridge/geometry/edge_grid.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "trajectory_generation_tools/trajectory/primitive_distance.h"

namespace kinematic_coverage::core {
namespace {

/// Tangents whose directions' cross product is below this are parallel.
constexpr double kParallelSine = 1e-9;
/// Waypoints closer than this to the one before are dropped, m.
constexpr double kSameWaypointDistance = 1e-3;
/// How many times a curve's sampling is doubled to keep its clearance, at most.
constexpr int kCurveRefinements = 3;
/// Segments of the fine polyline a curve's own clearance is measured on.
constexpr int kCurveClearanceSamples = 64;
/// Walls farther than the wall distance plus this from a segment do not count, m.
constexpr double kReachBeyondWallDistance = 1.0;

/// A distance from the walls and the point of the measured segment where it is.
using Clearance = std::pair<Point2, double>;

/// Where the tangent lines of two poses of a curve meet (between them): the corner of the
/// curve's tangent polygon; their middle where the tangents are nearly parallel.
Point2 tangentCorner(const Pose2& a, const Pose2& b) {
  const Point2 u(std::cos(a.yaw), std::sin(a.yaw));
  const Point2 v(std::cos(b.yaw), std::sin(b.yaw));
  const double denominator = u.x() * v.y() - u.y() * v.x();
  if (std::abs(denominator) < kParallelSine) return 0.5 * (a.position() + b.position());
  const Point2 d = b.position() - a.position();
  const double t = (d.x() * v.y() - d.y() * v.x()) / denominator;
  return a.position() + t * u;
}

/// The point of the segment a-b nearest to the segment c-d (an end of one of them is
/// nearest unless they cross; then the nearest of those).
Point2 nearestPointOn(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  Point2 best = a;
  double best_distance = distanceToSegment(a, c, d);
  for (const Point2& p : {b, closestPointOnSegment(c, a, b), closestPointOnSegment(d, a, b)}) {
    const double distance = distanceToSegment(p, c, d);
    if (distance < best_distance) {
      best_distance = distance;
      best = p;
    }
  }
  return best;
}

/// The hull and holes of an area, indexed for the distance of a segment from them up to a
/// reach (farther walls do not count: the reach is returned instead).
class WallProximity {
 public:
  WallProximity(const PolygonWithHoles& free_area, double reach) : reach_(reach) {
    const auto add = [&](const Ring& ring) {
      for (std::size_t i = 0; i < ring.size(); ++i) {
        starts_.push_back(ring[i]);
        ends_.push_back(ring[(i + 1) % ring.size()]);
      }
    };
    add(free_area.hull);
    for (const Ring& hole : free_area.holes) add(hole);
    EdgeGrid::Layout layout;
    layout.margin = reach;
    layout.padding = reach;
    grid_ = EdgeGrid(starts_, ends_, layout);
  }

  /// The distance of the segment a-b from the walls (at most the reach), and where.
  Clearance of(const Point2& a, const Point2& b) const {
    Clearance least = {a, reach_};
    ids_.clear();
    grid_.collect(grid_.cellsOf(a.cwiseMin(b), a.cwiseMax(b)), &ids_);
    const PathPrimitive segment = PathPrimitive::segment(a, b);
    for (int id : ids_) {
      const double distance = distancePrimitiveToSegment(segment, starts_[id], ends_[id]);
      if (distance < least.second) least = {nearestPointOn(a, b, starts_[id], ends_[id]), distance};
    }
    return least;
  }

  /// The least distance of the polyline from the walls, and where.
  Clearance ofPolyline(const std::vector<Point2>& points) const {
    Clearance least = {points.front(), reach_};
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
      const Clearance leg = of(points[i], points[i + 1]);
      if (leg.second < least.second) least = leg;
    }
    return least;
  }

 private:
  double reach_;
  std::vector<Point2> starts_;
  std::vector<Point2> ends_;
  EdgeGrid grid_;
  mutable std::vector<int> ids_;
};

/// The waypoints of a curve after its start: `steps` poses on it (inscribed), or the corners
/// of the polygon of its tangents at steps + 1 poses and its end (circumscribed).
std::vector<Point2> curvePoints(const PathPrimitive& curve, int steps, bool tangent_polygon) {
  std::vector<Point2> points;
  for (int k = 0; k < steps; ++k) {
    const Pose2 next = curve.poseAt(double(k + 1) / steps);
    points.push_back(tangent_polygon ? tangentCorner(curve.poseAt(double(k) / steps), next)
                                     : next.position());
  }
  if (tangent_polygon) points.push_back(curve.endPose().position());
  return points;
}

/// The waypoints of a curve after its start: the coarsest sampling (from kMaxTurnStep of
/// heading, doubled up to kCurveRefinements times), inscribed or circumscribed, whose legs
/// keep `target` or the curve's own clearance, whichever is less; the clearest one tried
/// where none does.
std::vector<Point2> curveWaypoints(const PathPrimitive& curve, const WallProximity& walls,
                                   double target) {
  const Point2 start = curve.startPose().position();
  std::vector<Point2> fine = {start};
  for (const Point2& p : curvePoints(curve, kCurveClearanceSamples, false)) fine.push_back(p);
  const double kept = std::min(target, walls.ofPolyline(fine).second) - kClearanceTolerance;
  const int coarsest = std::max(
      1, static_cast<int>(std::ceil(curve.turnAngle() / AutopilotMissionBuilder::kMaxTurnStep)));
  std::vector<Point2> best;
  double best_clearance = -1.0;
  for (int refinement = 0, steps = coarsest; refinement <= kCurveRefinements;
       ++refinement, steps *= 2) {
    for (bool tangent_polygon : {false, true}) {
      std::vector<Point2> points = curvePoints(curve, steps, tangent_polygon);
      std::vector<Point2> legs = {start};
      legs.insert(legs.end(), points.begin(), points.end());
      const double clearance = walls.ofPolyline(legs).second;
      if (clearance >= kept) return points;
      if (clearance > best_clearance) {
        best_clearance = clearance;
        best = std::move(points);
      }
    }
  }
  return best;
}

/// The polyline an autopilot is sent along, and the clearance from the walls of the path
/// it drives when it cuts each vertex by a radius (see AutopilotMissionBuilder).
class CutPath {
 public:
  CutPath(const std::vector<AutopilotWaypoint>& waypoints, const WallProximity& walls,
          const PolygonWithHoles& free_area, double wall_distance)
      : walls_(walls) {
    along_.push_back(0.0);
    for (const AutopilotWaypoint& waypoint : waypoints) {
      if (!points_.empty()) {
        along_.push_back(along_.back() + (waypoint.position - points_.back()).norm());
      }
      points_.push_back(waypoint.position);
    }
    // The shortest way in from a start nearer than the wall distance to a wall, and out to
    // such a goal, is left out, as the trajectory's clearance leaves it out.
    const auto in_band = [&](const Point2& p) {
      return !keepsClearance(distanceToBoundary(p, free_area), wall_distance);
    };
    from_ = in_band(points_.front()) ? along_[1] : 0.0;
    to_ = in_band(points_.back()) ? along_[along_.size() - 2] : along_.back();
  }

  /// The least distance from the walls of the legs, and the point where.
  Clearance legClearance() const {
    Clearance least = {points_.front(), std::numeric_limits<double>::infinity()};
    for (std::size_t i = 0; i + 1 < points_.size(); ++i) {
      if (along_[i] < from_ || along_[i + 1] > to_) continue;
      const Clearance leg = walls_.of(points_[i], points_[i + 1]);
      if (leg.second < least.second) least = leg;
    }
    return least;
  }

  /// The distance from the walls of the chord that cuts vertex i, from `radius` before it
  /// to `radius` after it but not past a held vertex (which the autopilot reaches) nor into
  /// the legs left out, and the point where; infinity for no chord.
  Clearance chordClearance(std::size_t i, double radius, const std::vector<bool>& held) const {
    double before = std::max(along_[i] - radius, from_);
    double after = std::min(along_[i] + radius, to_);
    for (std::size_t k = i; k-- > 0 && along_[k] > before;) {
      if (held[k]) before = along_[k];
    }
    for (std::size_t k = i + 1; k < points_.size() && along_[k] < after; ++k) {
      if (held[k]) after = along_[k];
    }
    if (before >= along_[i] || after <= along_[i]) {
      return {points_[i], std::numeric_limits<double>::infinity()};
    }
    return walls_.of(pointAt(before), pointAt(after));
  }

 private:
  /// The point at arc length s, clamped to the polyline.
  Point2 pointAt(double s) const {
    if (s <= 0.0) return points_.front();
    if (s >= along_.back()) return points_.back();
    const std::size_t i = static_cast<std::size_t>(
        std::upper_bound(along_.begin(), along_.end(), s) - along_.begin());
    const double length = along_[i] - along_[i - 1];
    const double t = length > 0.0 ? (s - along_[i - 1]) / length : 0.0;
    return points_[i - 1] + t * (points_[i] - points_[i - 1]);
  }

  const WallProximity& walls_;
  std::vector<Point2> points_;
  std::vector<double> along_;
  double from_ = 0.0;
  double to_ = 0.0;
};

/// Holds the waypoints whose cut by `radius` would come nearer the walls than the
/// waypoint path keeps (at most the wall distance), and measures what the cut path keeps.
void holdWhereCutsComeNear(const WallProximity& walls, const PolygonWithHoles& free_area,
                           double wall_distance, double radius, AutopilotMission* mission) {
  const CutPath cut_path(mission->waypoints, walls, free_area, wall_distance);
  Clearance least = cut_path.legClearance();
  const double kept = std::min(wall_distance, least.second) - kClearanceTolerance;
  std::vector<bool> held(mission->waypoints.size());
  for (std::size_t i = 0; i < held.size(); ++i) held[i] = mission->waypoints[i].hold;
  // Holding a vertex only shortens its neighbours' chords, so one pass in order settles
  // them all.
  for (std::size_t i = 1; i + 1 < held.size(); ++i) {
    if (!held[i] && cut_path.chordClearance(i, radius, held).second < kept) {
      held[i] = true;
      mission->waypoints[i].hold = true;
    }
  }
  for (std::size_t i = 1; i + 1 < held.size(); ++i) {
    if (held[i]) continue;
    const Clearance chord = cut_path.chordClearance(i, radius, held);
    if (chord.second < least.second) least = chord;
  }
  std::tie(mission->closest_cut, mission->corner_cut_clearance_m) = least;
}

}  // namespace

double AutopilotMissionBuilder::speedOn(const PathPrimitive& primitive) const {
  const double curvature = primitive.curvature();
  if (primitive.kind() == PrimitiveKind::kSegment || !(curvature > 0.0)) return vehicle_.v_max;
  return std::min(vehicle_.v_max, vehicle_.yaw_rate_max / curvature);
}

AutopilotMission AutopilotMissionBuilder::build(const std::vector<PathPrimitive>& path,
                                                const PolygonWithHoles& free_area,
                                                double wall_distance) const {
  const WallProximity walls(free_area, wall_distance + kReachBeyondWallDistance);
  AutopilotMission mission;
  const auto add = [&](const Point2& p, double speed) {
    if (mission.waypoints.empty() ||
        (p - mission.waypoints.back().position).norm() > kSameWaypointDistance) {
      mission.waypoints.push_back({p, speed, false});
    }
  };
  for (const PathPrimitive& primitive : path) {
    if (primitive.kind() == PrimitiveKind::kRotation) {
      // A sharp corner: the trajectory stops and turns on the spot there.
      if (!mission.waypoints.empty()) mission.waypoints.back().hold = true;
      continue;
    }
    const double speed = speedOn(primitive);
    if (mission.waypoints.empty()) add(primitive.startPose().position(), speed);
    if (primitive.kind() == PrimitiveKind::kSegment) {
      add(primitive.endPose().position(), speed);
      continue;
    }
    for (const Point2& p : curveWaypoints(primitive, walls, wall_distance)) add(p, speed);
  }
  if (mission.waypoints.size() < 2) return mission;
  holdWhereCutsComeNear(walls, free_area, wall_distance, corner_cutting_radius_, &mission);
  return mission;
}

}  // namespace kinematic_coverage::core
