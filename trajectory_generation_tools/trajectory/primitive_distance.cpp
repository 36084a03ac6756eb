#include "trajectory_generation_tools/trajectory/primitive_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

double segmentToSegment(const Point2& p0, const Point2& p1, const Point2& a, const Point2& b) {
  const double o1 = cross(p0, p1, a);
  const double o2 = cross(p0, p1, b);
  const double o3 = cross(a, b, p0);
  const double o4 = cross(a, b, p1);
  if (((o1 < 0.0 && o2 > 0.0) || (o1 > 0.0 && o2 < 0.0)) &&
      ((o3 < 0.0 && o4 > 0.0) || (o3 > 0.0 && o4 < 0.0))) {
    return 0.0;
  }
  // Otherwise the nearest pair has an end of one of them (touching included: then 0).
  return std::min({distanceToSegment(a, p0, p1), distanceToSegment(b, p0, p1),
                   distanceToSegment(p0, a, b), distanceToSegment(p1, a, b)});
}

bool arcContainsPoint(const PathPrimitive& arc, const Point2& p) {
  const Point2 d = p - arc.centre();
  return arcContainsAngle(arc, std::atan2(d.y(), d.x()));
}

double arcToSegment(const PathPrimitive& arc, const Point2& a, const Point2& b) {
  double best =
      std::min({distancePointToPrimitive(a, arc), distancePointToPrimitive(b, arc),
                distanceToSegment(arc.start(), a, b), distanceToSegment(arc.end(), a, b)});
  const double length = (b - a).norm();
  if (!(length > 0.0)) return best;
  const Point2 u = (b - a) / length;
  const Point2 n(-u.y(), u.x());
  const Point2 ca = arc.centre() - a;
  const double along = ca.dot(u);   // where the perpendicular from the centre meets the line
  const double offset = ca.dot(n);  // signed distance of the centre from the line
  const double r = arc.radius();
  if (std::abs(offset) <= r) {
    const double half_chord = std::sqrt(std::max(0.0, r * r - offset * offset));
    for (const double t : {along - half_chord, along + half_chord}) {
      if (t >= 0.0 && t <= length && arcContainsPoint(arc, a + t * u)) return 0.0;
    }
  }
  if (along >= 0.0 && along <= length) {
    for (const double side : {-1.0, 1.0}) {
      if (arcContainsAngle(arc, std::atan2(side * n.y(), side * n.x()))) {
        best = std::min(best, std::abs(offset + side * r));
      }
    }
  }
  return best;
}

}  // namespace

bool arcContainsAngle(const PathPrimitive& arc, double angle) {
  const double sweep = arc.sweep();
  if (std::abs(sweep) >= 2.0 * M_PI) return true;
  const double travelled = sweep >= 0.0 ? angle - arc.startAngle() : arc.startAngle() - angle;
  double within = std::fmod(travelled, 2.0 * M_PI);
  if (within < 0.0) within += 2.0 * M_PI;
  return within <= std::abs(sweep) + kArcAngleTolerance ||
         within >= 2.0 * M_PI - kArcAngleTolerance;
}

double distancePointToPrimitive(const Point2& p, const PathPrimitive& primitive) {
  switch (primitive.kind()) {
    case PrimitiveKind::kSegment:
      return distanceToSegment(p, primitive.start(), primitive.end());
    case PrimitiveKind::kRotation:
      return (p - primitive.start()).norm();
    case PrimitiveKind::kArc: {
      const Point2 d = p - primitive.centre();
      const double from_centre = d.norm();
      if (from_centre > 0.0 && arcContainsAngle(primitive, std::atan2(d.y(), d.x()))) {
        return std::abs(from_centre - primitive.radius());
      }
      if (!(from_centre > 0.0)) return primitive.radius();
      return std::min((p - primitive.start()).norm(), (p - primitive.end()).norm());
    }
    case PrimitiveKind::kClothoid: {
      const std::vector<Point2> chords = primitive.polyline(kClothoidDistanceTolerance);
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t i = 1; i < chords.size(); ++i) {
        best = std::min(best, distanceToSegment(p, chords[i - 1], chords[i]));
      }
      return std::max(0.0, best - kClothoidDistanceTolerance);
    }
  }
  return 0.0;
}

double distancePrimitiveToSegment(const PathPrimitive& primitive, const Point2& a,
                                  const Point2& b) {
  switch (primitive.kind()) {
    case PrimitiveKind::kSegment:
      return segmentToSegment(primitive.start(), primitive.end(), a, b);
    case PrimitiveKind::kRotation:
      return distanceToSegment(primitive.start(), a, b);
    case PrimitiveKind::kArc:
      return arcToSegment(primitive, a, b);
    case PrimitiveKind::kClothoid: {
      const std::vector<Point2> chords = primitive.polyline(kClothoidDistanceTolerance);
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t i = 1; i < chords.size(); ++i) {
        best = std::min(best, segmentToSegment(chords[i - 1], chords[i], a, b));
      }
      return std::max(0.0, best - kClothoidDistanceTolerance);
    }
  }
  return 0.0;
}

}  // namespace kinematic_coverage::core
