#pragma once

namespace kinematic_coverage::core {

/// How the corners of a waypoint path are smoothed (`smoothing_strategy`).
enum class SmoothingStrategy {
  /// As kGlobal, keeping what the sharp path sees (PathCoverageCheck), with wider arcs and
  /// bulb turns among the candidates.
  kCoverageSafe,
  /// Every corner's smoothing chosen jointly, minimising traversal time (GlobalPathSmoother).
  kGlobal,
  /// The thesis's Algorithm 1, corner by corner (PathSmoother).
  kLocal,
};

}  // namespace kinematic_coverage::core
