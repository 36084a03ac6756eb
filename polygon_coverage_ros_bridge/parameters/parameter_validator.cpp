#include "polygon_coverage_ros_bridge/parameters/parameter_validator.h"

#include <cmath>
#include <string>
#include <tuple>

#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/parameters/parameter_choices.h"

namespace kinematic_coverage::core {
namespace {

void requirePositive(const char* name, double value, const char* unit) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw InvalidInputError(std::string(name) + " = " + formatNumber(value) +
                            " is out of range: it must be a finite number > 0 (" + unit + ")");
  }
}

void requireNonNegative(const char* name, double value, const char* unit) {
  if (!(std::isfinite(value) && value >= 0.0)) {
    throw InvalidInputError(std::string(name) + " = " + formatNumber(value) +
                            " is out of range: it must be a finite number >= 0 (" + unit + ")");
  }
}

/// A share: 0 <= value < upper, or value <= upper where `upper_included`; `note` ends the
/// message.
void requireShare(const char* name, double value, double upper, bool upper_included,
                  const char* note = "") {
  if (!(std::isfinite(value) && value >= 0.0 &&
        (upper_included ? value <= upper : value < upper))) {
    throw InvalidInputError(std::string(name) + " = " + formatNumber(value) +
                            " is out of range: it must be in [0, " + formatNumber(upper) +
                            (upper_included ? "]" : ")") + note);
  }
}

void requireOpenAngle(const char* name, double value) {
  if (!(std::isfinite(value) && value > 0.0 && value < M_PI)) {
    throw InvalidInputError(std::string(name) + " = " + formatNumber(value) +
                            " is out of range: it must be in (0, pi) rad");
  }
}

/// gap_clearance in (0, wall_distance], or the wall distance's stand-in; any value when the
/// wall distance is 0 (no gaps then).
void requireGapClearance(const PlannerParameters& p) {
  if (p.wall_distance > 0.0 && p.gap_clearance != kClearanceOfWallDistance &&
      !(std::isfinite(p.gap_clearance) && p.gap_clearance > 0.0 &&
        p.gap_clearance <= p.wall_distance)) {
    throw InvalidInputError("gap_clearance = " + formatNumber(p.gap_clearance) +
                            " is out of range: it must be in (0, wall_distance = " +
                            formatNumber(p.wall_distance) + "] (m), or wall_distance");
  }
}

/// The current's fluctuation, the navigation error and their seed.
void validateDisturbance(const PlannerParameters& p) {
  requireNonNegative("current_sigma", p.current_sigma, "m/s");
  requireNonNegative("navigation_sigma", p.navigation_sigma, "m");
  requirePositive("current_time_constant", p.current_time_constant, "s");
  requirePositive("navigation_time_constant", p.navigation_time_constant, "s");
  const double seed = p.disturbance_seed;
  if (!(std::isfinite(seed) && seed >= 0.0 && seed < 4294967296.0 && seed == std::floor(seed))) {
    throw InvalidInputError("disturbance_seed = " + formatNumber(seed) +
                            " is out of range: it must be an integer in [0, 4294967295]");
  }
}

/// The dynamic vehicle's mass, damping, thrusters and loop gains.
void validateRigidBody(const PlannerParameters& p) {
  requirePositive("mass", p.mass, "kg");
  requirePositive("inertia_yaw", p.inertia_yaw, "kg m^2");
  for (const auto& [name, value, unit] : {
           std::tuple<const char*, double, const char*>{"added_mass_surge", p.added_mass_surge,
                                                        "kg"},
           {"added_mass_sway", p.added_mass_sway, "kg"},
           {"added_inertia_yaw", p.added_inertia_yaw, "kg m^2"},
           {"damping_surge_linear", p.damping_surge_linear, "N s/m"},
           {"damping_sway_linear", p.damping_sway_linear, "N s/m"},
           {"damping_yaw_linear", p.damping_yaw_linear, "N m s/rad"},
           {"damping_surge_quadratic", p.damping_surge_quadratic, "N s^2/m^2"},
           {"damping_sway_quadratic", p.damping_sway_quadratic, "N s^2/m^2"},
           {"damping_yaw_quadratic", p.damping_yaw_quadratic, "N m s^2/rad^2"},
       }) {
    if (!(std::isfinite(value) && value >= 0.0)) {
      throw InvalidInputError(std::string(name) + " = " + formatNumber(value) +
                              " is out of range: it must be a finite number >= 0 (" + unit + ")");
    }
  }
  requirePositive("thrust_max", p.thrust_max, "N");
  requirePositive("yaw_torque_max", p.yaw_torque_max, "N m");
  requirePositive("surge_loop_gain", p.surge_loop_gain, "1/s");
  requirePositive("yaw_rate_loop_gain", p.yaw_rate_loop_gain, "1/s");
}

}  // namespace

void ParameterValidator::validate(const PlannerParameters& p) const {
  choiceOf("decomposition_type", p.decomposition_type, kDecompositionTypes);
  choiceOf("cell_joining", p.cell_joining, kCellJoinings);
  choiceOf("cost_function", p.cost_function, kCostFunctions);
  requirePositive("v_max", p.v_max, "m/s");
  requirePositive("a_max", p.a_max, "m/s^2");
  requirePositive("yaw_rate_max", p.yaw_rate_max, "rad/s");
  requireNonNegative("wall_distance", p.wall_distance, "m");
  choiceOf("sensor_model", p.sensor_model, kSensorModels);
  requireOpenAngle("lateral_fov", p.lateral_fov);
  requireOpenAngle("onward_fov", p.onward_fov);
  requirePositive("lateral_footprint", p.lateral_footprint, "m");
  requirePositive("sensor_distance", p.sensor_distance, "m");
  requireShare("lateral_overlap", p.lateral_overlap, 1.0, false);
  requirePositive("turning_radius", p.turning_radius, "m");
  choiceOf("offset_parts", p.offset_parts, kOffsetParts);
  requireGapClearance(p);
  choiceOf("smoothing_strategy", p.smoothing_strategy, kSmoothingStrategies);
  choiceOf("turn_curve", p.turn_curve, kTurnCurves);
  choiceOf("coverage_safe_area", p.coverage_safe_area, kCoverageSafeAreas);
  requirePositive("curvature_rate_max", p.curvature_rate_max, "1/m^2");
  if (p.smoothing_clearance != kClearanceOfWallDistance) {
    if (!(std::isfinite(p.smoothing_clearance) && p.smoothing_clearance >= 0.0)) {
      throw InvalidInputError("smoothing_clearance = " + formatNumber(p.smoothing_clearance) +
                              " is out of range: it must be a finite number >= 0 (m), or "
                              "wall_distance");
    }
  }
  if (!(std::isfinite(p.min_turning_radius) && p.min_turning_radius >= 0.0 &&
        p.min_turning_radius <= p.turning_radius)) {
    throw InvalidInputError(
        "min_turning_radius = " + formatNumber(p.min_turning_radius) +
        " is out of range: it must be in (0, turning_radius = " + formatNumber(p.turning_radius) +
        "], or 0 for equal to turning_radius (m)");
  }
  if (!(std::isfinite(p.max_turning_radius) &&
        (p.max_turning_radius == 0.0 || p.max_turning_radius >= p.turning_radius))) {
    throw InvalidInputError(
        "max_turning_radius = " + formatNumber(p.max_turning_radius) +
        " is out of range: it must be at least turning_radius = " + formatNumber(p.turning_radius) +
        ", or 0 for max(turning_radius, v_max / yaw_rate_max) (m)");
  }
  requirePositive("segment_sampling_distance", p.segment_sampling_distance, "m");
  requirePositive("arc_sampling_distance", p.arc_sampling_distance, "m");
  requirePositive("rotation_sampling_angle", p.rotation_sampling_angle, "rad");
  choiceOf("replanning_method", p.replanning_method, kReplanningMethods);
  requireShare("boundary_simplification", p.boundary_simplification, 0.5, true,
               " (a share of the sweep distance)");
  requireShare("replanning_sliver_fraction", p.replanning_sliver_fraction, 1.0, false);
  requireNonNegative("replanning_min_area", p.replanning_min_area, "m^2");
  requireNonNegative("replanning_simplify_tolerance", p.replanning_simplify_tolerance, "m");
  requirePositive("alpha", p.alpha, "m");
  choiceOf("vehicle_model", p.vehicle_model, kVehicleModels);
  validateRigidBody(p);
  requirePositive("yaw_gain", p.yaw_gain, "1/s");
  requirePositive("position_gain", p.position_gain, "1/s");
  requirePositive("position_tolerance", p.position_tolerance, "m");
  requireOpenAngle("yaw_tolerance", p.yaw_tolerance);
  for (const auto& [name, value] :
       {std::pair<const char*, double>{"current_x", p.current_x}, {"current_y", p.current_y}}) {
    if (!std::isfinite(value)) {
      throw InvalidInputError(std::string(name) + " = " + formatNumber(value) +
                              " is out of range: it must be a finite number (m/s)");
    }
  }
  validateDisturbance(p);
  requirePositive("sim_dt", p.sim_dt, "s");
  requirePositive("sim_time_limit", p.sim_time_limit, "s");
  // A discrete proportional loop with gain k corrects k * sim_dt of its error per step:
  // above 1 it overshoots what it aims at and oscillates.
  for (const auto& [name, gain] : {std::pair<const char*, double>{"yaw_gain", p.yaw_gain},
                                   {"surge_loop_gain", p.surge_loop_gain},
                                   {"yaw_rate_loop_gain", p.yaw_rate_loop_gain}}) {
    if (gain * p.sim_dt > 1.0) {
      throw InvalidInputError(std::string(name) + " = " + formatNumber(gain) +
                              " with sim_dt = " + formatNumber(p.sim_dt) +
                              " is out of range: " + name + " * sim_dt must be <= 1");
    }
  }
}

}  // namespace kinematic_coverage::core
