#pragma once

#include <cstddef>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// Two directions closer than this (radians, modulo pi) count as one sweep direction.
constexpr double kDirectionTolerance = 1e-3;

/// The unit vector of a direction angle.
Point2 directionVector(double direction);

/// Rotates p so that `direction` becomes the +y axis (lanes vertical, sweep along x).
Point2 toSweepFrame(const Point2& p, double direction);

/// The inverse of toSweepFrame.
Point2 fromSweepFrame(const Point2& p, double direction);

/// Width of a ring across `direction`: the distance between the two outermost lines
/// parallel to it. The cell's altitude when swept with lanes parallel to `direction`.
double altitude(const Ring& ring, double direction);

/// True when every line parallel to `direction` meets the simple ring in at most one
/// interval, so that lanes parallel to `direction` sweep it without leaving it.
bool isMonotone(const Ring& ring, double direction);

/// The edge directions of the rings, modulo pi, deduplicated within
/// kDirectionTolerance; at most `max_count`, preferring the directions with the most
/// total edge length (a long wall is the best lane direction; a 2 000-vertex hull must
/// not give 2 000 decompositions).
std::vector<double> candidateDirections(const std::vector<Ring>& rings, std::size_t max_count);

}  // namespace kinematic_coverage::core
