#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// Named tolerances for double geometry (metres); topology-deciding predicates use CGAL.
constexpr double kLengthTolerance = 1e-9;
/// Two consecutive poses closer than this (metres) are at the same position: a waypoint
/// path skips the second; a trajectory sees their two footprints, not the convex hull of
/// them (docs/REFERENCE.md, Sensor footprint and coverage); a trajectory's pose at the
/// position of the one before is a turn in place.
constexpr double kSamePositionTolerance = 1e-9;
/// m: a path keeps a clearance c (wall_distance, smoothing_clearance) when no point of it is
/// nearer than c minus this to the hull and holes, so that pieces lying on the offset free
/// area's boundary keep it (docs/REFERENCE.md, Collisions and clearance).
constexpr double kClearanceTolerance = 1e-3;

/// True when a distance of `distance_m` keeps the clearance `clearance_m`, within
/// kClearanceTolerance.
inline bool keepsClearance(double distance_m, double clearance_m) {
  return distance_m >= clearance_m - kClearanceTolerance;
}

/// The axis-aligned bounds of the points (empty for none).
Eigen::AlignedBox2d boundingBox(const std::vector<Point2>& points);

/// Signed area of a ring: positive when counter-clockwise.
double signedArea(const Ring& ring);

/// Area of the hull minus the areas of the holes.
double area(const PolygonWithHoles& polygon);

/// The centroid of the area (hull less holes); the hull's first vertex when it has no area.
Point2 centroid(const PolygonWithHoles& polygon);

/// Sum of the areas of disjoint polygons (the parts of an offset free area), m^2.
double area(const std::vector<PolygonWithHoles>& parts);

/// The z component of (b - a) x (c - a): > 0 when a, b, c turn left.
double cross(const Point2& a, const Point2& b, const Point2& c);

/// Distance from p to the closed segment [a, b]; a degenerate segment is its point.
double distanceToSegment(const Point2& p, const Point2& a, const Point2& b);

/// The point of the closed segment [a, b] nearest to p.
Point2 closestPointOnSegment(const Point2& p, const Point2& a, const Point2& b);

/// Distance from p to the boundary of a ring.
double distanceToRing(const Point2& p, const Ring& ring);

/// Distance from p to the boundary of the polygon (hull and holes).
double distanceToBoundary(const Point2& p, const PolygonWithHoles& polygon);

/// Even-odd point-in-ring test; points on the boundary may go either way.
bool insideRing(const Point2& p, const Ring& ring);

/// True when p lies inside the hull and outside every hole, or within `tolerance`
/// of the boundary.
bool contains(const PolygonWithHoles& polygon, const Point2& p, double tolerance = 0.0);

/// True when the closed segment [a, b] lies inside the polygon (touching the boundary
/// allowed within `tolerance`): no proper crossing of any edge and its midpoints inside.
bool segmentInside(const PolygonWithHoles& polygon, const Point2& a, const Point2& b,
                   double tolerance = 1e-9);

/// Convex hull of points (Andrew's monotone chain), counter-clockwise, without collinear
/// vertices; the points themselves when fewer than 3.
Ring convexHull(std::vector<Point2> points);

/// Heading of the vector from a to b, in (-pi, pi].
double headingOf(const Point2& a, const Point2& b);

/// Wraps an angle into (-pi, pi].
double wrapAngle(double angle);

/// The points of a polyline as poses, each facing along the leg that leaves it (the last
/// along the leg that reaches it; a single point faces yaw 0): the waypoints of a path.
std::vector<Pose2> legHeadingPoses(const std::vector<Point2>& points);

}  // namespace kinematic_coverage::core
