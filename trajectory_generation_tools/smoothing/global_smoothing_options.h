#pragma once

#include <algorithm>
#include <optional>

#include "polygon_coverage_ros_bridge/planner/planner_parameters.h"
#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"

namespace kinematic_coverage::core {

/// What the global smoothing strategy may choose from and what it minimises.
struct GlobalSmoothingOptions {
  /// The robot's preferred turning radius r: the largest radius an arc uses (m, > 0).
  double turning_radius = 1.0;
  /// The smallest radius a corner may use instead (m, in (0, turning_radius]); a tighter
  /// arc is driven slower, at min(v_max, yaw_rate_max * radius).
  double min_turning_radius = 1.0;
  /// A larger radius a corner may also use (m; at most turning_radius: none). An arc is
  /// driven at min(v_max, yaw_rate_max * radius): where the preferred radius is tighter
  /// than v_max / yaw_rate_max, a wider arc keeps more speed through the turn.
  double max_turning_radius = 0.0;
  /// The velocity model of trajectory timing that the traversal time is minimised under.
  double v_max = 0.5;
  double a_max = 0.2;
  double yaw_rate_max = 0.5;
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
  /// Bulb turns (BulbTurnSmoothing) among the candidates of corner pairs turning the same
  /// way. Coverage-safe smoothing sets it: a bulb turn drives along the boundary the lanes
  /// end at and sees the strip beyond their ends, which inner arcs cut. The `global` and
  /// `local` strategies keep the candidates they were measured with (docs/BENCHMARKS.md).
  bool bulb_turns = false;

  /// The options that `parameters` give: `min_turning_radius` 0 means equal to
  /// `turning_radius`; `coverage_preserving` sets the preserved sensor, the strategy
  /// `coverage_safe` the safe sensor, of `parameters`, and its largest radius
  /// (`max_turning_radius`, 0: the radius of an arc at v_max if that is wider).
  static GlobalSmoothingOptions fromParameters(const PlannerParameters& parameters) {
    GlobalSmoothingOptions options;
    options.turning_radius = parameters.turning_radius;
    options.min_turning_radius = parameters.min_turning_radius > 0.0 ? parameters.min_turning_radius
                                                                     : parameters.turning_radius;
    options.v_max = parameters.v_max;
    options.a_max = parameters.a_max;
    options.yaw_rate_max = parameters.yaw_rate_max;
    if (parameters.coverage_preserving) {
      options.preserved_sensor = FrustumSensor::fromParameters(parameters);
    }
    if (parameters.smoothing_strategy == "coverage_safe") {
      options.makeCoverageSafe(FrustumSensor::fromParameters(parameters), parameters.wall_distance);
      options.max_turning_radius =
          parameters.max_turning_radius > 0.0
              ? parameters.max_turning_radius
              : std::max(parameters.turning_radius, parameters.v_max / parameters.yaw_rate_max);
    }
    return options;
  }

  /// Coverage-safe smoothing (`smoothing_strategy: coverage_safe`) for `sensor` and the
  /// planner's `wall_distance`: the safe sensor and its candidates, bulb turns included.
  void makeCoverageSafe(const FrustumSensor& sensor, double wall_distance_m) {
    safe_sensor = sensor;
    wall_distance = wall_distance_m;
    bulb_turns = true;
  }
};

}  // namespace kinematic_coverage::core
