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

/// What coverage-safe smoothing keeps of what the sharp path sees (`coverage_safe_area`).
enum class CoverageSafeArea {
  /// The reachable area: what the robot sees whichever way it faces from the offset free
  /// area's edge.
  kReachable,
  /// All of the free area, the wall band beyond the reachable area included, which lanes
  /// along a wall and turns in place see.
  kFree,
};

}  // namespace kinematic_coverage::core
