#include "coverage_system/parameters/stage_options.h"

#include <algorithm>
#include <cstdint>

#include "coverage_system/parameters/parameter_choices.h"
#include "coverage_system/parameters/parameter_schema.h"

namespace kinematic_coverage::core {
namespace {

// The mappings of a parameter set: the composers of a stage's whole options
// (planningOptionsOf, globalSmoothingOptionsOf, trajectoryOptionsOf, robotModelOf,
// remainingAreaOptionsOf) check the set once (checkParameters), then map with these.

VehicleLimits vehicleLimits(const PlannerParameters& p) {
  return VehicleLimits{p.v_max, p.a_max, p.yaw_rate_max, p.turning_radius};
}

double smoothingClearance(const PlannerParameters& p) {
  return p.smoothing_clearance == kClearanceOfWallDistance ? p.wall_distance
                                                           : p.smoothing_clearance;
}

double gapClearance(const PlannerParameters& p) {
  return p.gap_clearance == kClearanceOfWallDistance ? p.wall_distance : p.gap_clearance;
}

SensorOptions sensorOptions(const PlannerParameters& p) {
  SensorOptions options;
  options.model = choiceOf(p.sensor_model, kSensorModels);
  options.lateral_fov = p.lateral_fov;
  options.onward_fov = p.onward_fov;
  options.lateral_footprint = p.lateral_footprint;
  options.sensor_distance = p.sensor_distance;
  options.lateral_overlap = p.lateral_overlap;
  return options;
}

GlobalSmoothingOptions globalSmoothingOptions(const PlannerParameters& p) {
  GlobalSmoothingOptions options;
  options.vehicle = vehicleLimits(p);
  options.min_turning_radius = p.min_turning_radius > 0.0 ? p.min_turning_radius : p.turning_radius;
  options.clearance = smoothingClearance(p);
  const FrustumSensor sensor = FrustumSensor::fromOptions(sensorOptions(p));
  if (p.coverage_preserving) options.preserved_sensor = sensor;
  if (choiceOf(p.smoothing_strategy, kSmoothingStrategies) == SmoothingStrategy::kCoverageSafe) {
    options.makeCoverageSafe(sensor, p.wall_distance);
    options.coverage_safe_area = choiceOf(p.coverage_safe_area, kCoverageSafeAreas);
    options.max_turning_radius = p.max_turning_radius > 0.0
                                     ? p.max_turning_radius
                                     : std::max(p.turning_radius, p.v_max / p.yaw_rate_max);
  }
  return options;
}

const PlannerParameters& validated(const PlannerParameters& parameters) {
  checkParameters(parameters);
  return parameters;
}

}  // namespace

PlanningOptions planningOptionsOf(const PlannerParameters& parameters) {
  const PlannerParameters& p = validated(parameters);
  PlanningOptions options;
  options.vehicle = vehicleLimits(p);
  options.sensor = sensorOptions(p);
  options.decomposition_type = choiceOf(p.decomposition_type, kDecompositionTypes);
  options.cell_joining = choiceOf(p.cell_joining, kCellJoinings);
  options.boundary_simplification =
      p.boundary_simplification * options.frustumSensor().sweepDistance();
  options.cost_function = choiceOf(p.cost_function, kCostFunctions);
  options.wall_distance = p.wall_distance;
  options.offset_parts = choiceOf(p.offset_parts, kOffsetParts);
  options.gap_clearance = gapClearance(p);
  options.offset_miter_limit = p.offset_miter_limit;
  options.coverage_repair = p.coverage_repair;
  options.max_memory_mb = p.max_memory_mb;
  options.gtsp_effort = p.gtsp_effort;
  return options;
}

VehicleLimits vehicleLimitsOf(const PlannerParameters& parameters) {
  return vehicleLimits(parameters);
}

SensorOptions sensorOptionsOf(const PlannerParameters& parameters) {
  return sensorOptions(parameters);
}

FrustumSensor sensorOf(const PlannerParameters& parameters) {
  return FrustumSensor::fromOptions(sensorOptionsOf(parameters));
}

double smoothingClearanceOf(const PlannerParameters& parameters) {
  return smoothingClearance(parameters);
}

double gapClearanceOf(const PlannerParameters& parameters) { return gapClearance(parameters); }

double boundarySimplificationOf(const PlannerParameters& parameters) {
  return parameters.boundary_simplification * sensorOf(parameters).sweepDistance();
}

SegmentCost segmentCostOf(const PlannerParameters& parameters) {
  return SegmentCost(choiceOf(parameters.cost_function, kCostFunctions), vehicleLimits(parameters));
}

GlobalSmoothingOptions globalSmoothingOptionsOf(const PlannerParameters& parameters) {
  return globalSmoothingOptions(validated(parameters));
}

TrajectoryOptions trajectoryOptionsOf(const PlannerParameters& parameters) {
  const PlannerParameters& p = validated(parameters);
  TrajectoryOptions options;
  options.smoothing = p.smoothing;
  options.strategy = choiceOf(p.smoothing_strategy, kSmoothingStrategies);
  options.global = globalSmoothingOptions(p);
  options.segment_sampling_distance = p.segment_sampling_distance;
  options.arc_sampling_distance = p.arc_sampling_distance;
  options.rotation_sampling_angle = p.rotation_sampling_angle;
  options.turn_curve = choiceOf(p.turn_curve, kTurnCurves);
  options.curvature_rate_max = p.curvature_rate_max;
  options.wall_distance = p.wall_distance;
  return options;
}

TrajectoryOptions trajectoryOptionsOf(const PlannerParameters& parameters,
                                      const std::vector<PolygonWithHoles>& exact_offset_parts) {
  TrajectoryOptions options = trajectoryOptionsOf(parameters);
  options.global.exact_offset_parts = exact_offset_parts;
  return options;
}

RobotModel robotModelOf(const PlannerParameters& parameters) {
  const PlannerParameters& p = validated(parameters);
  RobotModel model;
  model.vehicle_model = choiceOf(p.vehicle_model, kVehicleModels);
  model.vehicle = vehicleLimits(p);
  RigidBodyParameters& body = model.body;
  body.mass = p.mass;
  body.added_mass_surge = p.added_mass_surge;
  body.added_mass_sway = p.added_mass_sway;
  body.inertia_yaw = p.inertia_yaw;
  body.added_inertia_yaw = p.added_inertia_yaw;
  body.damping_surge_linear = p.damping_surge_linear;
  body.damping_sway_linear = p.damping_sway_linear;
  body.damping_yaw_linear = p.damping_yaw_linear;
  body.damping_surge_quadratic = p.damping_surge_quadratic;
  body.damping_sway_quadratic = p.damping_sway_quadratic;
  body.damping_yaw_quadratic = p.damping_yaw_quadratic;
  body.thrust_max = p.thrust_max;
  body.yaw_torque_max = p.yaw_torque_max;
  body.sway_actuated = p.sway_actuated;
  model.surge_loop_gain = p.surge_loop_gain;
  model.yaw_rate_loop_gain = p.yaw_rate_loop_gain;
  model.controller = choiceOf(p.controller, kTrackingControllers);
  model.braking = p.braking;
  model.tracking_natural_frequency = p.tracking_natural_frequency;
  model.tracking_damping = p.tracking_damping;
  model.pose_rate = p.pose_rate;
  model.los_lookahead = p.los_lookahead;
  model.yaw_gain = p.yaw_gain;
  model.position_gain = p.position_gain;
  model.position_tolerance = p.position_tolerance;
  model.yaw_tolerance = p.yaw_tolerance;
  model.current_x = p.current_x;
  model.current_y = p.current_y;
  model.disturbance.current_sigma = p.current_sigma;
  model.disturbance.current_time_constant = p.current_time_constant;
  model.disturbance.navigation_sigma = p.navigation_sigma;
  model.disturbance.navigation_time_constant = p.navigation_time_constant;
  model.disturbance.seed = static_cast<std::uint32_t>(p.disturbance_seed);
  model.sim_dt = p.sim_dt;
  model.sim_time_limit = p.sim_time_limit;
  return model;
}

RemainingAreaOptions remainingAreaOptionsOf(const PlannerParameters& parameters) {
  const PlannerParameters& p = validated(parameters);
  RemainingAreaOptions options;
  options.method = choiceOf(p.replanning_method, kReplanningMethods);
  options.sensor = sensorOptions(p);
  options.sliver_fraction = p.replanning_sliver_fraction;
  options.min_area = p.replanning_min_area;
  options.simplify_tolerance = p.replanning_simplify_tolerance;
  options.alpha = p.alpha;
  return options;
}

}  // namespace kinematic_coverage::core
