#pragma once

#include <optional>
#include <vector>

#include "polygon_coverage_ros_bridge/base/vehicle_limits.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"
#include "trajectory_generation_tools/smoothing/smoothing_strategy.h"

namespace kinematic_coverage::core {

/// What the global smoothing strategy may choose from and what it minimises.
struct GlobalSmoothingOptions {
  /// The robot: its preferred turning radius r, the largest radius an arc uses but for
  /// max_turning_radius (m, > 0), and the velocity model of trajectory timing that the
  /// traversal time is minimised under (v_max, a_max, yaw_rate_max).
  VehicleLimits vehicle;
  /// The smallest radius a corner may use instead (m, in (0, turning_radius]); a tighter
  /// arc is driven slower, at min(v_max, yaw_rate_max * radius).
  double min_turning_radius = 1.0;
  /// A larger radius a corner may also use (m; at most turning_radius: none). An arc is
  /// driven at min(v_max, yaw_rate_max * radius): where the preferred radius is tighter
  /// than v_max / yaw_rate_max, a wider arc keeps more speed through the turn.
  double max_turning_radius = 0.0;
  /// Set: coverage-preserving smoothing; a corner is smoothed only where this sensor still
  /// sees what it saw from the sharp corner (CornerCoverageCheck).
  std::optional<FrustumSensor> preserved_sensor;
  /// Set: coverage-safe smoothing (`smoothing_strategy: coverage_safe`); the path as a
  /// whole must see what its sharp version sees with this sensor (PathCoverageCheck), and
  /// a corner whose smoothing loses area nothing else sees is smoothed only in ways that
  /// keep it with the rest of the path sharp (PathCoverageCheck::lostCellsReplacing) or
  /// left sharp.
  std::optional<FrustumSensor> safe_sensor;
  /// Coverage-safe only: the planner's wall distance (m, >= 0), which shapes the reachable
  /// area whose coverage is kept.
  double wall_distance = 0.0;
  /// Coverage-safe only: what is kept of what the sharp path sees, the reachable area or
  /// all of the free area (`coverage_safe_area`).
  CoverageSafeArea coverage_safe_area = CoverageSafeArea::kReachable;
  /// Coverage-safe only: the exact offset free area of the free area and wall_distance
  /// (exactOffsetParts), whose rim bounds the reachable area, when the caller has it (a
  /// plan's `exact_offset_parts`); empty: computed from the free area.
  std::vector<PolygonWithHoles> exact_offset_parts;
  /// Bulb turns (BulbTurnSmoothing) among the candidates of corner pairs turning the same
  /// way. Coverage-safe smoothing sets it: a bulb turn drives along the boundary the lanes
  /// end at and sees the strip beyond their ends, which inner arcs cut. The `global` and
  /// `local` strategies keep the candidates they were measured with (docs/BENCHMARKS.md).
  bool bulb_turns = false;
  /// m (>= 0): the distance every arc and leg piece keeps from the hull and holes
  /// (smoothing_clearance); 0: only no contact, as the thesis.
  double clearance = 0.0;

  /// Coverage-safe smoothing (`smoothing_strategy: coverage_safe`) for `sensor` and the
  /// planner's `wall_distance`: the safe sensor and its candidates, bulb turns included.
  void makeCoverageSafe(const FrustumSensor& sensor, double wall_distance_m) {
    safe_sensor = sensor;
    wall_distance = wall_distance_m;
    bulb_turns = true;
  }
};

}  // namespace kinematic_coverage::core
