#pragma once

#include <string>

namespace kinematic_coverage::core {

/// The value of a clearance (smoothing_clearance, gap_clearance) that stands for the wall
/// distance, written `wall_distance` in mission files, `--set`, config/*.yaml and the
/// nodes' parameters.
constexpr double kClearanceOfWallDistance = -1.0;

/// Every parameter (docs/REFERENCE.md, Parameters) with its default. The same names are the keys
/// of mission files, `--set name=value`, config/default.yaml and the nodes' private
/// parameters. Units: metres, radians, seconds.
struct PlannerParameters {
  std::string decomposition_type = "boustrophedon";  ///< or "trapezoidal"
  /// Where boustrophedon cells end: "critical_points" (Choset's cells) or
  /// "longest_overlap" (one cell goes on across each critical point).
  std::string cell_joining = "longest_overlap";
  std::string cost_function = "time";  ///< "distance", "time" or "waypoints"
  double v_max = 0.5;                  ///< m/s
  double a_max = 0.2;                  ///< m/s^2
  double yaw_rate_max = 0.5;           ///< rad/s
  double wall_distance = 1.0;          ///< m kept from hull and holes
  /// Where the wall offset splits the free area: "all" parts reachable through gaps with at
  /// least gap_clearance, planned and joined through them, or only the "largest".
  std::string offset_parts = "all";
  /// m: the least clearance of a gap between parts that transits pass, in (0, wall_distance];
  /// by default the wall distance (kClearanceOfWallDistance): parts beyond narrower gaps are
  /// not entered. Ignored when wall_distance is 0.
  double gap_clearance = kClearanceOfWallDistance;
  /// Share of the sweep distance by which the offset free area's boundary may move inward
  /// before it is decomposed (BoundarySimplification); in [0, 0.5], 0: decomposed exactly.
  double boundary_simplification = 0.1;
  std::string sensor_model = "frustum";  ///< or "line"
  double lateral_fov = 2.27;             ///< rad
  double onward_fov = 0.52;              ///< rad
  double lateral_footprint = 2.0;        ///< m, line sensor only
  double sensor_distance = 3.0;          ///< m between sensor and bottom
  double lateral_overlap = 0.4;          ///< fraction in [0, 1)
  /// Patches driven where the planned sweeps leave reachable area unseen (UnseenAreaRepair).
  bool coverage_repair = true;
  bool smoothing = true;        ///< false: segments and rotations
  double turning_radius = 1.0;  ///< m
  /// "coverage_safe": as "global", keeping what the sharp path sees; "global": every
  /// corner's smoothing chosen jointly, minimising traversal time; "local": the thesis's
  /// Algorithm 1, corner by corner.
  std::string smoothing_strategy = "coverage_safe";
  double min_turning_radius = 0.0;  ///< m, global only; 0: equal to turning_radius
  /// m, coverage_safe only: the largest radius a corner may use, so that an arc is driven
  /// at up to v_max; 0: max(turning_radius, v_max / yaw_rate_max).
  double max_turning_radius = 0.0;
  bool coverage_preserving = false;  ///< global only: smooth only where nothing goes unseen
  /// coverage_safe only: "reachable" or "free", what is kept of what the unsmoothed path sees
  std::string coverage_safe_area = "reachable";
  double segment_sampling_distance = 0.5;  ///< m
  double arc_sampling_distance = 0.1;      ///< m
  double rotation_sampling_angle = 0.2;    ///< rad
  std::string turn_curve = "arc";          ///< "arc" or "clothoid"
  /// m: the least distance of smoothed turns to walls and obstacles; by default the wall
  /// distance (kClearanceOfWallDistance), 0: no contact (the thesis).
  double smoothing_clearance = kClearanceOfWallDistance;
  double curvature_rate_max = 2.0;              ///< 1/m^2, clothoid turns only
  std::string replanning_method = "footprint";  ///< "convex_hull", "concave_hull", "footprint"
  double replanning_sliver_fraction =
      0.2;                           ///< remaining parts narrower than this x sweep spacing go
  double replanning_min_area = 1.0;  ///< m^2, smaller remaining parts go
  double replanning_simplify_tolerance = 0.1;  ///< m, boundary simplification of the remaining area
  double alpha = 2.0;                          ///< m, alpha-shape parameter
  // The robot model of `coverage_tool simulate` and auv_simulator (TrajectoryFollower).
  std::string vehicle_model = "dynamic";  ///< "dynamic" or "kinematic"
  // The dynamic vehicle (RigidBodyParameters: the BlueROV2's, Wu 2018).
  double mass = 11.5;                      ///< kg
  double added_mass_surge = 5.5;           ///< kg
  double added_mass_sway = 12.7;           ///< kg
  double inertia_yaw = 0.16;               ///< kg m^2
  double added_inertia_yaw = 0.12;         ///< kg m^2
  double damping_surge_linear = 4.03;      ///< N s/m
  double damping_sway_linear = 6.22;       ///< N s/m
  double damping_yaw_linear = 0.07;        ///< N m s/rad
  double damping_surge_quadratic = 18.18;  ///< N s^2/m^2
  double damping_sway_quadratic = 21.66;   ///< N s^2/m^2
  double damping_yaw_quadratic = 1.55;     ///< N m s^2/rad^2
  double thrust_max = 113.0;               ///< N
  double yaw_torque_max = 30.0;            ///< N m
  double surge_loop_gain = 5.0;            ///< 1/s: surge-speed loop bandwidth
  double yaw_rate_loop_gain = 10.0;        ///< 1/s: yaw-rate loop bandwidth
  double yaw_gain = 5.0;                   ///< 1/s: yaw-rate command per rad of heading error
  double position_gain = 1.5;              ///< 1/s: surge-speed command per m to the target
  double position_tolerance = 0.05;        ///< m: a position target counts as reached within it
  double yaw_tolerance = 0.05;             ///< rad: a turn-in-place target is reached within it
  double current_x = 0.0;                  ///< m/s: constant water current along x
  double current_y = 0.0;                  ///< m/s: constant water current along y
  double current_sigma = 0.0;              ///< m/s: current fluctuation, per axis
  double current_time_constant = 60.0;     ///< s: correlation time of the fluctuation
  double navigation_sigma = 0.0;           ///< m: navigation position error, per axis
  double navigation_time_constant = 2.0;   ///< s: correlation time of the navigation error
  double disturbance_seed = 1.0;           ///< an integer in [0, 2^32): the disturbance's draw
  double sim_dt = 0.1;                     ///< s: simulation time step
  double sim_time_limit = 36000.0;         ///< s: simulated time after which a run gives up
};

}  // namespace kinematic_coverage::core
