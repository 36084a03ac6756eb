#pragma once

#include <cstddef>

#include "polygon_coverage_ros_bridge/base/vehicle_limits.h"
#include "polygon_coverage_ros_bridge/decomposition/sweep_line_decomposition.h"
#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"
#include "polygon_coverage_ros_bridge/route/offset_part_joiner.h"
#include "polygon_coverage_ros_bridge/route/segment_cost.h"
#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"

namespace kinematic_coverage::core {

/// What the planner (Chapter 3's pipeline, and the replanner's planning of the remaining
/// area) reads: composed once from a checked parameter set (planningOptionsOf), so that the
/// planner hands each stage its part and checks nothing again.
struct PlanningOptions {
  VehicleLimits vehicle;
  SensorOptions sensor;
  DecompositionType decomposition_type = DecompositionType::kBoustrophedon;
  CellJoining cell_joining = CellJoining::kLongestOverlap;
  /// m: how far the offset free area's boundary may move inward before it is decomposed.
  double boundary_simplification = 0.0;
  CostFunction cost_function = CostFunction::kTime;
  /// m kept from the hull and the holes.
  double wall_distance = 1.0;
  OffsetParts offset_parts = OffsetParts::kAll;
  /// m: the least clearance of a gap that transits pass (the wall distance resolved).
  double gap_clearance = 1.0;
  /// Wall distances beyond which the wall offset's mitres are squared off.
  double offset_miter_limit = kDefaultMiterLimit;
  bool coverage_repair = true;
  /// MB a plan may take by its estimate (planMemoryEstimateBytes); 0: half the machine's
  /// physical memory.
  double max_memory_mb = 0.0;
  /// Multiplies the generalized TSP's stall window (gtsp_effort).
  double gtsp_effort = 1.0;
  /// s: the generalized TSP's safety cap (GtspOptions::time_limit_s); not a parameter, so
  /// that a plan does not depend on the machine's speed unless the cap is hit, which the
  /// plan reports (CoveragePlan::gtsp_time_capped).
  double gtsp_time_limit_s = 60.0;
  /// Generalized TSP nodes above which transitions are routed between nearby cells only
  /// (LazyTransitionCosts); not a parameter (tests lower it to reach that path on small maps).
  std::size_t dense_transition_nodes = 3000;
  /// Route corners above which the visibility graph keeps no all-pairs table and searches
  /// routes on demand (VisibilityGraph::kOnDemandNodes); not a parameter (tests lower it).
  std::size_t dense_route_corners = 4000;

  FrustumSensor frustumSensor() const { return FrustumSensor::fromOptions(sensor); }
  SegmentCost segmentCost() const { return SegmentCost(cost_function, vehicle); }
};

}  // namespace kinematic_coverage::core
