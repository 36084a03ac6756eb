#pragma once

#include <vector>

#include "trajectory_generation_tools/path/path_primitive.h"

namespace kinematic_coverage::core {

/// Primitives' ends further apart than this (metres) break a path's continuity.
constexpr double kJoinPositionTolerance = 1e-6;
/// Headings at a joint that differ by more than this (radians) are not G1 continuous.
constexpr double kJoinHeadingTolerance = 1e-6;
/// A segment or arc no longer than this (metres) is a point: sampling and timing skip it,
/// as its heading is numerically meaningless.
constexpr double kDegenerateLength = kJoinPositionTolerance;
/// A rotation turning no more than this (radians) is no rotation.
constexpr double kDegenerateTurn = 1e-12;

/// True for a primitive that neither moves nor turns (within the tolerances above).
bool isDegenerate(const PathPrimitive& primitive);

/// Throws InvalidInputError, naming the primitive, for a path that cannot be sampled or
/// timed: a non-finite coordinate, angle or radius, an arc radius not positive, or
/// consecutive primitives whose end and start are more than kJoinPositionTolerance apart.
void validatePrimitivePath(const std::vector<PathPrimitive>& path);

}  // namespace kinematic_coverage::core
