#pragma once

#include "coverage_system/parameters/planner_parameters.h"
#include "coverage_system/parameters/planning_options.h"
#include "polygon_coverage_ros_bridge/base/vehicle_limits.h"
#include "polygon_coverage_ros_bridge/decomposition/sweep_line_decomposition.h"
#include "polygon_coverage_ros_bridge/route/offset_part_joiner.h"
#include "polygon_coverage_ros_bridge/route/segment_cost.h"
#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"
#include "polygon_coverage_ros_bridge/sweeps/sensor_options.h"
#include "trajectory_generation_tools/replanning/remaining_area_options.h"
#include "trajectory_generation_tools/simulation/robot_model.h"
#include "trajectory_generation_tools/smoothing/global_smoothing_options.h"
#include "trajectory_generation_tools/trajectory/trajectory_options.h"

namespace kinematic_coverage::core {

// The one place where the flat parameter set of mission files, `--set`, config/*.yaml and
// the nodes' private parameters (PlannerParameters) becomes the options each stage reads.
// The composers of a stage's whole options (planningOptionsOf, globalSmoothingOptionsOf,
// trajectoryOptionsOf, robotModelOf, remainingAreaOptionsOf) check the set once
// (checkParameters) and throw InvalidInputError naming the first parameter out of range;
// the single mappings below them (vehicleLimitsOf, sensorOf, ...) take a set the readers
// have checked and check nothing again.

/// The planner's options: the vehicle limits, the sensor, the decomposition, the route and
/// the repair.
PlanningOptions planningOptionsOf(const PlannerParameters& parameters);

/// v_max, a_max, yaw_rate_max and turning_radius.
VehicleLimits vehicleLimitsOf(const PlannerParameters& parameters);

/// sensor_model, lateral_fov, onward_fov, lateral_footprint, sensor_distance and
/// lateral_overlap.
SensorOptions sensorOptionsOf(const PlannerParameters& parameters);

/// The sensor of sensorOptionsOf.
FrustumSensor sensorOf(const PlannerParameters& parameters);

/// smoothing_clearance in metres: the wall distance unless set otherwise.
double smoothingClearanceOf(const PlannerParameters& parameters);

/// gap_clearance in metres: the wall distance unless set otherwise.
double gapClearanceOf(const PlannerParameters& parameters);

/// boundary_simplification as a distance (m): that share of the sensor's sweep distance.
double boundarySimplificationOf(const PlannerParameters& parameters);

/// The planner's segment cost: cost_function under the vehicle limits.
SegmentCost segmentCostOf(const PlannerParameters& parameters);

/// The global and coverage-safe strategies' options: `min_turning_radius` 0 means equal
/// to `turning_radius`; `coverage_preserving` sets the preserved sensor, the strategy
/// `coverage_safe` the safe sensor, bulb turns and the largest radius
/// (`max_turning_radius`, 0: the radius of an arc at v_max if that is wider).
GlobalSmoothingOptions globalSmoothingOptionsOf(const PlannerParameters& parameters);

/// smoothing, smoothing_strategy (with globalSmoothingOptionsOf), the sampling intervals
/// and the vehicle limits.
TrajectoryOptions trajectoryOptionsOf(const PlannerParameters& parameters);

/// As above, for a plan's waypoints: coverage-safe smoothing takes the plan's exact offset
/// free area (`exact_offset_parts`) instead of offsetting the free area again.
TrajectoryOptions trajectoryOptionsOf(const PlannerParameters& parameters,
                                      const std::vector<PolygonWithHoles>& exact_offset_parts);

/// The simulated robot: the vehicle limits, the controllers' gains and tolerances, the
/// current, sim_dt and sim_time_limit.
RobotModel robotModelOf(const PlannerParameters& parameters);

/// replanning_method, the remaining area's clean-up (replanning_sliver_fraction,
/// replanning_min_area, replanning_simplify_tolerance), alpha, and the sensor.
RemainingAreaOptions remainingAreaOptionsOf(const PlannerParameters& parameters);

}  // namespace kinematic_coverage::core
