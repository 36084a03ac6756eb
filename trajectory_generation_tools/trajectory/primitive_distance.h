#pragma once

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/path/path_primitive.h"

namespace kinematic_coverage::core {

/// Angles within this (radians) of an arc's angular range count as on the arc.
constexpr double kArcAngleTolerance = 1e-12;
/// A clothoid's distances are measured to its chords (PathPrimitive::polyline) within this
/// (m) and lowered by it, so that they never exceed the true distance.
constexpr double kClothoidDistanceTolerance = 1e-5;

/// The exact distance from a primitive's points (a segment, an arc, or a rotation's one
/// position) to the closed segment [a, b] (a point when a == b); 0 when they meet. For an
/// arc this compares the segment's ends with the arc, the arc's ends with the segment,
/// the line-circle crossings and the two points of the circle on the perpendicular from
/// the centre to the segment, which is where any interior minimum lies. For a clothoid, a
/// lower bound within kClothoidDistanceTolerance.
double distancePrimitiveToSegment(const PathPrimitive& primitive, const Point2& a, const Point2& b);

/// The exact distance from p to a primitive's points (a clothoid's: a lower bound within
/// kClothoidDistanceTolerance).
double distancePointToPrimitive(const Point2& p, const PathPrimitive& primitive);

/// True when the polar angle `angle` about an arc's centre lies within the arc's sweep
/// (within kArcAngleTolerance). Only meaningful for arcs.
bool arcContainsAngle(const PathPrimitive& arc, double angle);

}  // namespace kinematic_coverage::core
