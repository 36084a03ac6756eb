#pragma once

#include <vector>

#include "polygon_coverage_ros_bridge/base/vehicle_limits.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// What the planner minimises over its transitions and its generalized TSP (`cost_function`).
enum class CostFunction {
  kDistance,   ///< metres
  kTime,       ///< seconds, rest to rest on every segment
  kWaypoints,  ///< the number of segments
};

/// The cost of driving one straight segment under `cost_function` (docs/REFERENCE.md, Parameters),
/// the edge weight of the planner's transitions and of its generalized TSP.
///
/// "distance": the length. "time": rest-to-rest with a trapezoidal velocity profile
/// (v_max, a_max), so a path costs the sum over its segments, stopping at every bend.
/// "waypoints": one per segment. A zero-length segment costs 0 in every mode.
/// Every mode is a non-decreasing, subadditive function of the length, so a straight
/// segment never costs more than any detour between its ends.
class SegmentCost {
 public:
  /// Throws InvalidInputError for v_max or a_max of `limits` not positive and finite when
  /// `cost_function` is kTime.
  SegmentCost(CostFunction cost_function, const VehicleLimits& limits);

  /// The cost of a straight segment of `length` metres (>= 0). Throws InvalidInputError
  /// for a negative or non-finite length.
  double ofLength(double length) const;

  /// The cost of the straight segment from a to b.
  double of(const Point2& a, const Point2& b) const;

  /// True when a longer segment always costs more ("distance", "time"; not "waypoints"):
  /// a cheapest route then bends only where it wraps around a wall.
  bool increasesWithLength() const { return cost_function_ != CostFunction::kWaypoints; }

  /// The sum of the costs of the path's segments (0 for fewer than two points).
  double pathCost(const std::vector<Point2>& path) const;

 private:
  CostFunction cost_function_;
  VehicleLimits limits_;
};

/// The length of a polyline, metres (0 for fewer than two points).
double pathLength(const std::vector<Point2>& path);

}  // namespace kinematic_coverage::core
