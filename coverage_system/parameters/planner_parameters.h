#pragma once

#include <string>

namespace kinematic_coverage::core {

/// The value of a clearance (smoothing_clearance, gap_clearance) that stands for the wall
/// distance, written `wall_distance` in mission files, `--set`, config/*.yaml and the
/// nodes' parameters.
constexpr double kClearanceOfWallDistance = -1.0;

/// The values of every parameter: storage only. Each parameter is declared once, with its
/// unit, default, range and description, in the parameter schema (parameterSchema(),
/// parameter_schema.h); the constructor sets the schema's defaults. Units: metres, radians,
/// seconds.
struct PlannerParameters {
  PlannerParameters();

  std::string decomposition_type{};
  std::string cell_joining{};
  std::string cost_function{};
  double v_max{};
  double a_max{};
  double yaw_rate_max{};
  double wall_distance{};
  std::string offset_parts{};
  double gap_clearance{};
  double offset_miter_limit{};
  double boundary_simplification{};
  double max_memory_mb{};
  double gtsp_effort{};
  std::string sensor_model{};
  double lateral_fov{};
  double onward_fov{};
  double lateral_footprint{};
  double sensor_distance{};
  double lateral_overlap{};
  bool coverage_repair{};
  bool smoothing{};
  double turning_radius{};
  std::string smoothing_strategy{};
  double min_turning_radius{};
  double max_turning_radius{};
  bool coverage_preserving{};
  std::string coverage_safe_area{};
  double segment_sampling_distance{};
  double arc_sampling_distance{};
  double rotation_sampling_angle{};
  double trajectory_output_spacing{};
  double corner_cutting_radius{};
  double mission_depth{};
  std::string projection{};
  std::string turn_curve{};
  double smoothing_clearance{};
  double curvature_rate_max{};
  std::string replanning_method{};
  double replanning_sliver_fraction{};
  double replanning_min_area{};
  double replanning_simplify_tolerance{};
  double alpha{};
  std::string vehicle_model{};
  double mass{};
  double added_mass_surge{};
  double added_mass_sway{};
  double inertia_yaw{};
  double added_inertia_yaw{};
  double damping_surge_linear{};
  double damping_sway_linear{};
  double damping_yaw_linear{};
  double damping_surge_quadratic{};
  double damping_sway_quadratic{};
  double damping_yaw_quadratic{};
  double thrust_max{};
  double yaw_torque_max{};
  bool sway_actuated{};
  double surge_loop_gain{};
  double yaw_rate_loop_gain{};
  std::string controller{};
  bool braking{};
  double tracking_natural_frequency{};
  double tracking_damping{};
  double pose_rate{};
  double los_lookahead{};
  double yaw_gain{};
  double position_gain{};
  double position_tolerance{};
  double yaw_tolerance{};
  double current_x{};
  double current_y{};
  double current_sigma{};
  double current_time_constant{};
  double navigation_sigma{};
  double navigation_time_constant{};
  double disturbance_seed{};
  double sim_dt{};
  double sim_time_limit{};
};

}  // namespace kinematic_coverage::core
