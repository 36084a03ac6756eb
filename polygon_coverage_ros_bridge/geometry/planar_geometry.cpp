#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace kinematic_coverage::core {

Eigen::AlignedBox2d boundingBox(const std::vector<Point2>& points) {
  Eigen::AlignedBox2d box;
  for (const Point2& p : points) box.extend(p);
  return box;
}

double signedArea(const Ring& ring) {
  double twice_area = 0.0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const Point2& a = ring[i];
    const Point2& b = ring[(i + 1) % n];
    twice_area += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * twice_area;
}

double area(const PolygonWithHoles& polygon) {
  double result = std::abs(signedArea(polygon.hull));
  for (const Ring& hole : polygon.holes) result -= std::abs(signedArea(hole));
  return result;
}

namespace {

/// Twice the ring's area times its centroid (counter-clockwise positive), and twice its
/// area, about `origin` (for precision far from the frame's origin).
std::pair<Point2, double> weightedCentroid(const Ring& ring, const Point2& origin) {
  Point2 moment = Point2::Zero();
  double twice_area = 0.0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const Point2 a = ring[i] - origin;
    const Point2 b = ring[(i + 1) % n] - origin;
    const double term = a.x() * b.y() - b.x() * a.y();
    moment += term * (a + b) / 3.0;
    twice_area += term;
  }
  return {moment, twice_area};
}

}  // namespace

Point2 centroid(const PolygonWithHoles& polygon) {
  if (polygon.hull.empty()) return Point2::Zero();
  const Point2 origin = polygon.hull.front();
  auto [moment, twice_area] = weightedCentroid(polygon.hull, origin);
  const double sign = twice_area < 0.0 ? -1.0 : 1.0;
  moment *= sign;
  twice_area *= sign;
  for (const Ring& hole : polygon.holes) {
    const auto [hole_moment, hole_twice_area] = weightedCentroid(hole, origin);
    const double hole_sign = hole_twice_area < 0.0 ? -1.0 : 1.0;
    moment -= hole_sign * hole_moment;
    twice_area -= hole_sign * hole_twice_area;
  }
  if (!(twice_area > 0.0)) return origin;
  return origin + moment / twice_area;
}

double cross(const Point2& a, const Point2& b, const Point2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

Point2 closestPointOnSegment(const Point2& p, const Point2& a, const Point2& b) {
  const Point2 ab = b - a;
  const double length_sq = ab.squaredNorm();
  if (length_sq <= 0.0) return a;
  const double t = std::clamp((p - a).dot(ab) / length_sq, 0.0, 1.0);
  return a + t * ab;
}

double distanceToSegment(const Point2& p, const Point2& a, const Point2& b) {
  return (p - closestPointOnSegment(p, a, b)).norm();
}

double distanceToRing(const Point2& p, const Ring& ring) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    best = std::min(best, distanceToSegment(p, ring[i], ring[(i + 1) % n]));
  }
  return best;
}

double distanceToBoundary(const Point2& p, const PolygonWithHoles& polygon) {
  double best = distanceToRing(p, polygon.hull);
  for (const Ring& hole : polygon.holes) best = std::min(best, distanceToRing(p, hole));
  return best;
}

bool insideRing(const Point2& p, const Ring& ring) {
  bool inside = false;
  for (std::size_t i = 0, n = ring.size(), j = n - 1; i < n; j = i++) {
    const Point2& a = ring[i];
    const Point2& b = ring[j];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x_cross = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x_cross) inside = !inside;
    }
  }
  return inside;
}

double area(const std::vector<PolygonWithHoles>& parts) {
  double total = 0.0;
  for (const PolygonWithHoles& part : parts) total += area(part);
  return total;
}

bool contains(const PolygonWithHoles& polygon, const Point2& p, double tolerance) {
  // The crossing tests first: they are cheaper than distances, and most points asked
  // about lie inside, where the distance is not needed.
  const auto inside = [&]() {
    if (!insideRing(p, polygon.hull)) return false;
    for (const Ring& hole : polygon.holes) {
      if (insideRing(p, hole)) return false;
    }
    return true;
  };
  return inside() || (tolerance > 0.0 && distanceToBoundary(p, polygon) <= tolerance);
}

namespace {

/// Parameters t in (0, 1) where the segment [a, b] meets the segment [c, d].
void appendCrossings(const Point2& a, const Point2& b, const Point2& c, const Point2& d,
                     std::vector<double>* ts) {
  const Point2 r = b - a;
  const Point2 s = d - c;
  const double denominator = r.x() * s.y() - r.y() * s.x();
  const Point2 ca = c - a;
  if (std::abs(denominator) > 0.0) {
    const double t = (ca.x() * s.y() - ca.y() * s.x()) / denominator;
    const double u = (ca.x() * r.y() - ca.y() * r.x()) / denominator;
    if (t > 0.0 && t < 1.0 && u >= 0.0 && u <= 1.0) ts->push_back(t);
  }
  // Endpoints of [c, d] on or near [a, b] (also covers the collinear case).
  const double length_sq = r.squaredNorm();
  if (length_sq <= 0.0) return;
  for (const Point2& q : {c, d}) {
    const double t = (q - a).dot(r) / length_sq;
    if (t > 0.0 && t < 1.0) ts->push_back(t);
  }
}

}  // namespace

bool segmentInside(const PolygonWithHoles& polygon, const Point2& a, const Point2& b,
                   double tolerance) {
  std::vector<double> ts = {0.0, 1.0};
  auto collect = [&](const Ring& ring) {
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      appendCrossings(a, b, ring[i], ring[(i + 1) % n], &ts);
    }
  };
  collect(polygon.hull);
  for (const Ring& hole : polygon.holes) collect(hole);
  std::sort(ts.begin(), ts.end());
  for (double t : ts) {
    if (!contains(polygon, a + t * (b - a), tolerance)) return false;
  }
  for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
    if (ts[i + 1] - ts[i] <= 0.0) continue;
    const Point2 mid = a + 0.5 * (ts[i] + ts[i + 1]) * (b - a);
    if (!contains(polygon, mid, tolerance)) return false;
  }
  return true;
}

double headingOf(const Point2& a, const Point2& b) {
  return wrapAngle(std::atan2(b.y() - a.y(), b.x() - a.x()));
}

std::vector<Pose2> legHeadingPoses(const std::vector<Point2>& points) {
  std::vector<Pose2> poses;
  poses.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double yaw = i + 1 < points.size() ? headingOf(points[i], points[i + 1])
                       : i > 0               ? headingOf(points[i - 1], points[i])
                                             : 0.0;
    poses.push_back({points[i].x(), points[i].y(), yaw});
  }
  return poses;
}

Ring convexHull(std::vector<Point2> points) {
  std::sort(points.begin(), points.end(), [](const Point2& a, const Point2& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  if (points.size() < 3) return Ring(points.begin(), points.end());
  Ring hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

double wrapAngle(double angle) {
  if (!std::isfinite(angle)) return angle;
  double wrapped = std::remainder(angle, 2.0 * M_PI);
  if (wrapped <= -M_PI) wrapped += 2.0 * M_PI;
  return wrapped;
}

}  // namespace kinematic_coverage::core
