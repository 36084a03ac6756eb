#include "coverage_system/parameters/parameter_schema.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <tuple>
#include <type_traits>
#include <utility>

#include "coverage_system/parameters/parameter_choices.h"
#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"
#include "trajectory_generation_tools/simulation/robot_simulator.h"

namespace kinematic_coverage::core {
namespace {

using P = PlannerParameters;

/// The word a clearance's value may be: the wall distance.
constexpr const char* kWallDistanceWord = "wall_distance";

/// The width config/default.yaml's comments are wrapped at.
constexpr std::size_t kCommentWidth = 92;

/// Numbers > 0.
NumberRange positive() {
  NumberRange range;
  range.lower = 0.0;
  range.lower_open = true;
  return range;
}

/// Numbers >= 0.
NumberRange nonNegative() {
  NumberRange range;
  range.lower = 0.0;
  return range;
}

/// Numbers between `lower` and `upper`, each end open or closed.
NumberRange interval(double lower, bool lower_open, double upper, bool upper_open) {
  NumberRange range;
  range.lower = lower;
  range.lower_open = lower_open;
  range.upper = upper;
  range.upper_open = upper_open;
  return range;
}

/// A loop gain: > 0, and its product with the time step at most 1 (a discrete proportional
/// loop corrects gain * sim_dt of its error per step; above 1 it overshoots and oscillates).
NumberRange loopGain() {
  NumberRange range = positive();
  range.product_parameter = "sim_dt";
  range.product_max = 1.0;
  return range;
}

/// The names of a name-valued parameter's choices.
template <typename Value, std::size_t N>
std::vector<std::string> namesOf(const ParameterChoices<Value, N>& choices) {
  std::vector<std::string> names;
  for (const auto& choice : choices) names.emplace_back(choice.first);
  return names;
}

/// A number parameter.
ParameterDeclaration number(const char* name, double P::*member, const char* unit,
                            double default_value, NumberRange range, ParameterStage stage,
                            const char* description, const char* source = "") {
  return {name, member, unit, default_value, range, {}, nullptr, description, source, stage};
}

/// A clearance: a distance or the word for the wall distance (its default).
ParameterDeclaration clearance(const char* name, double P::*member, NumberRange range,
                               ParameterStage stage, const char* description) {
  return {name,        member, "m",  kClearanceOfWallDistance, range, {}, kWallDistanceWord,
          description, "",     stage};
}

/// A true/false parameter.
ParameterDeclaration flag(const char* name, bool P::*member, bool default_value,
                          ParameterStage stage, const char* description, const char* source = "") {
  return {name, member, "", default_value, {}, {}, nullptr, description, source, stage};
}

/// A name-valued parameter.
ParameterDeclaration choice(const char* name, std::string P::*member, const char* default_value,
                            std::vector<std::string> choices, ParameterStage stage,
                            const char* description) {
  return {name,        member, "",   std::string(default_value), {}, std::move(choices), nullptr,
          description, "",     stage};
}

/// Where the thesis's settings come from.
constexpr const char* kThesis = "the thesis's experiments (Chapter 4)";

/// The decomposition, the vehicle's limits, the route and the wall offset.
std::vector<ParameterDeclaration> planningDeclarations() {
  using S = ParameterStage;
  NumberRange gap = positive();
  gap.upper_parameter = "wall_distance";
  gap.unchecked_while_zero = "wall_distance";
  return {
      choice("decomposition_type", &P::decomposition_type, "boustrophedon",
             namesOf(kDecompositionTypes), S::kDecomposition,
             "Cell decomposition of the offset free area: boustrophedon or trapezoidal."),
      choice("cell_joining", &P::cell_joining, "longest_overlap", namesOf(kCellJoinings),
             S::kDecomposition,
             "Where boustrophedon cells end: critical_points (a new cell wherever the slice's "
             "connectivity changes: Choset's cells) or longest_overlap (across each critical "
             "point one cell goes on into the neighbour it shares the longest slice with: "
             "fewer, longer cells whose lanes line up; a map of at most 50 Choset cells is "
             "also planned with those, and the cheaper tour kept)."),
      choice("cost_function", &P::cost_function, "time", namesOf(kCostFunctions), S::kRoute,
             "Cost of a route for the GTSP: distance (m), time (s, rest-to-rest trapezoidal "
             "velocity profile per straight segment) or waypoints (count)."),
      number("v_max", &P::v_max, "m/s", 0.5, positive(), S::kVehicle,
             "Maximum speed, for the time cost, the trajectory timing and the robot model."),
      number("a_max", &P::a_max, "m/s^2", 0.2, positive(), S::kVehicle,
             "Maximum acceleration and deceleration, for the time cost, the trajectory "
             "timing and the robot model."),
      number("yaw_rate_max", &P::yaw_rate_max, "rad/s", 0.5, positive(), S::kVehicle,
             "Maximum yaw rate, for in-place rotations and arc speed (v <= yaw_rate_max * r)."),
      number("wall_distance", &P::wall_distance, "m", 1.0, nonNegative(), S::kWallOffset,
             "Distance kept from the hull and from every obstacle.", kThesis),
      choice("offset_parts", &P::offset_parts, "all", namesOf(kOffsetParts), S::kWallOffset,
             "Where the wall offset splits the free area (a strait narrower than two wall "
             "distances): all (every part reachable through gaps with at least gap_clearance "
             "planned, joined by transits through them) or largest (only the largest part; "
             "every other one named in a warning)."),
      clearance("gap_clearance", &P::gap_clearance, gap, S::kWallOffset,
                "The least clearance of a gap between parts that transits pass; "
                "wall_distance (the default): a part joined to the start's part only through "
                "narrower gaps is not entered (named in a warning, counted as unreachable). "
                "Every narrower transit allowed is warned of."),
      number("offset_miter_limit", &P::offset_miter_limit, "", kDefaultMiterLimit,
             interval(kMinMiterLimit, false, kMaxMiterLimit, false), S::kWallOffset,
             "Wall distances by which a corner of the offset free area may reach beyond "
             "the wall's corner before it is squared off (cut at the wall distance from "
             "it): at 6 (the default), every corner sharper than 19 degrees; at 2, sharper "
             "than 60 degrees; 1000, nearly the thesis's "
             "straight-skeleton offset, whose mitres at a rough shore's needles reach "
             "across the water and cut the area into parts its lanes do not reach."),
      number("boundary_simplification", &P::boundary_simplification, "", 0.1,
             interval(0.0, false, 0.5, false), S::kDecomposition,
             "Share of the sweep distance by which the offset free area's boundary may move "
             "inward before it is decomposed, so that cells follow the lake's shape, not its "
             "boundary noise (lanes still end at the exact boundary, routes and metrics use "
             "the exact areas); a free area too large for the wall offset is simplified "
             "within it too, with a warning, instead of refused; 0: exact."),
      number("max_memory_mb", &P::max_memory_mb, "MB", 0.0, nonNegative(), S::kDecomposition,
             "The memory a plan may take: right after the decomposition, before anything of "
             "the map's size is built, the plan's memory is estimated (the visibility graph, "
             "the transition costs and the generalized TSP grow with the square of the "
             "corners and the cells) and a map over this is refused, saying what reduces "
             "it; 0: half the machine's physical memory."),
      number("gtsp_effort", &P::gtsp_effort, "", 1.0, interval(1.0, false, 100.0, false), S::kRoute,
             "How long the generalized TSP searches for a cheaper visiting order: its stall "
             "window (the generations after which it stops when the best order has gained "
             "less than 0.1 %) is multiplied by this; a plan then takes about as many times "
             "as long to solve, for a tour rarely more than a few tenths of a percent "
             "cheaper (docs/BENCHMARKS.md, Lake charts)."),
  };
}

/// The sensor, the repair and the smoothing.
std::vector<ParameterDeclaration> sensingDeclarations() {
  using S = ParameterStage;
  NumberRange within_turning_radius = nonNegative();
  within_turning_radius.upper_parameter = "turning_radius";
  NumberRange beyond_turning_radius;
  beyond_turning_radius.lower_parameter = "turning_radius";
  beyond_turning_radius.zero_allowed = true;
  return {
      choice("sensor_model", &P::sensor_model, "frustum", namesOf(kSensorModels), S::kSensor,
             "Sensor model: frustum (a downward-looking camera) or line (a line sensor)."),
      number("lateral_fov", &P::lateral_fov, "rad", 2.27, interval(0.0, true, M_PI, true),
             S::kSensor, "The frustum's field of view across the heading.", kThesis),
      number("onward_fov", &P::onward_fov, "rad", 0.52, interval(0.0, true, M_PI, true), S::kSensor,
             "The frustum's field of view along the heading.", kThesis),
      number("lateral_footprint", &P::lateral_footprint, "m", 2.0, positive(), S::kSensor,
             "Footprint width of the line sensor (checked whatever the model)."),
      number("sensor_distance", &P::sensor_distance, "m", 3.0, positive(), S::kSensor,
             "Distance between the sensor and the bottom.", kThesis),
      number("lateral_overlap", &P::lateral_overlap, "", 0.4, interval(0.0, false, 1.0, true),
             S::kSensor, "Share of the footprint width that neighbouring sweeps have in common.",
             kThesis),
      flag("coverage_repair", &P::coverage_repair, true, S::kRepair,
           "true: where the planned sweeps leave reachable area unseen, put back the jogs "
           "removed near it and drive patches that see it (along the boundary beside it, out "
           "toward the exact offset, or through it), where they cost least."),
      flag("smoothing", &P::smoothing, true, S::kSmoothing,
           "true: smooth turns with arcs; false: the segment-only path with in-place "
           "rotations."),
      number("turning_radius", &P::turning_radius, "m", 1.0, positive(), S::kVehicle,
             "The robot's optimal turning radius: the radius of every arc (of the largest "
             "arcs with global).",
             kThesis),
      choice("smoothing_strategy", &P::smoothing_strategy, "coverage_safe",
             namesOf(kSmoothingStrategies), S::kSmoothing,
             "How corners are smoothed: coverage_safe (global with bulb turns along the "
             "boundary the lanes end at, keeping every reachable area the unsmoothed path "
             "sees), global (every corner's variant and radius chosen jointly, minimising "
             "traversal_time_s) or local (the thesis's Algorithm 1, corner by corner)."),
      number("min_turning_radius", &P::min_turning_radius, "m", 0.0, within_turning_radius,
             S::kSmoothing,
             "global and coverage_safe only: the smallest radius a corner may use, driven "
             "slower; 0: equal to turning_radius."),
      number("max_turning_radius", &P::max_turning_radius, "m", 0.0, beyond_turning_radius,
             S::kSmoothing,
             "coverage_safe only: the largest radius a corner may use, so that a robot whose "
             "turning_radius is tighter than v_max / yaw_rate_max keeps its speed through a "
             "turn where that loses no coverage; 0: max(turning_radius, v_max / "
             "yaw_rate_max)."),
      flag("coverage_preserving", &P::coverage_preserving, false, S::kSmoothing,
           "global and coverage_safe only: smooth a corner only where the sensor still sees "
           "what the sharp turn saw."),
      choice("coverage_safe_area", &P::coverage_safe_area, "reachable", namesOf(kCoverageSafeAreas),
             S::kSmoothing,
             "coverage_safe only: what the smoothed path keeps of what the unsmoothed path "
             "sees: reachable (the reachable area) or free (all of the free area, the wall "
             "band beyond the reachable area too)."),
  };
}

/// Sampling, turn curves, clearance and replanning.
std::vector<ParameterDeclaration> trajectoryDeclarations() {
  using S = ParameterStage;
  return {
      number("segment_sampling_distance", &P::segment_sampling_distance, "m", 0.5, positive(),
             S::kTrajectory, "Sampling distance of the trajectory along straight segments.",
             kThesis),
      number("arc_sampling_distance", &P::arc_sampling_distance, "m", 0.1, positive(),
             S::kTrajectory, "Sampling distance of the trajectory along arcs.", kThesis),
      number("rotation_sampling_angle", &P::rotation_sampling_angle, "rad", 0.2, positive(),
             S::kTrajectory, "Sampling angle of the trajectory during in-place rotations."),
      number("trajectory_output_spacing", &P::trajectory_output_spacing, "m", 0.0, nonNegative(),
             S::kTrajectory,
             "Thins the written trajectory files (trajectory.csv, trajectory.geojson) to one "
             "pose per this many metres, keeping every primitive's end poses, every rotation "
             "and a pose per 0.1 rad of every curve; 0: every sampled pose. Metrics, plot and "
             "mission files use every pose."),
      number("corner_cutting_radius", &P::corner_cutting_radius, "m", 2.0, nonNegative(),
             S::kTrajectory,
             "How far before a waypoint of the vehicle's mission files (mission.plan, "
             "mission.waypoints) the autopilot turns for the next one; the acceptance radius "
             "written, and what plan checks the cut corners' distance from the walls with.",
             "ArduPilot's WPNAV_RADIUS default, 200 cm (libraries/AC_WPNav/AC_WPNav.cpp, "
             "WPNAV_WP_RADIUS_CM), which ArduSub uses"),
      number("mission_depth", &P::mission_depth, "m", 0.0, nonNegative(), S::kTrajectory,
             "Depth below the surface of every waypoint of the vehicle's mission files, "
             "written as ArduSub reads it: the altitude -mission_depth relative to the "
             "surface (MAV_FRAME_GLOBAL_RELATIVE_ALT)."),
      choice("projection", &P::projection, "local", namesOf(kMapProjections), S::kTrajectory,
             "The plane a geo-referenced mission is planned in: local (the east-north frame "
             "at the datum, for areas within 50 km of it) or utm (the grid of the datum's UTM "
             "zone, from the datum: for longer lakes; an area where its point scale differs "
             "from 1 by more than 1e-3 is refused)."),
      choice("turn_curve", &P::turn_curve, "arc", namesOf(kTurnCurves), S::kSmoothing,
             "The curve of a smoothed turn between two straight legs: arc (the thesis's "
             "circular arc, whose curvature jumps where it meets a leg) or clothoid "
             "(clothoid-arc-clothoid, continuous in curvature, where the legs leave room and "
             "it comes no nearer an obstacle and sees no less than the arc; other arcs stay)."),
      number("curvature_rate_max", &P::curvature_rate_max, "1/m^2", 2.0, positive(), S::kVehicle,
             "How fast a clothoid's curvature may change per metre.",
             "driven at v_max it asks for a yaw acceleration of curvature_rate_max * v_max^2 = "
             "0.5 rad/s^2, which the dynamic vehicle's yaw-rate loop (yaw_rate_loop_gain 10 "
             "1/s) follows within 0.05 rad/s, a tenth of yaw_rate_max"),
      clearance("smoothing_clearance", &P::smoothing_clearance, nonNegative(), S::kSmoothing,
                "The distance every smoothed turn (arcs, clothoids, bulb turns) and the leg "
                "pieces between them keep from the walls and obstacles; wall_distance (the "
                "default): the distance the sweeps keep (within 1 mm). A smaller value lets "
                "turns into the wall band, and plan warns of the closest approach; 0 is the "
                "thesis's check: no contact. A corner that cannot keep it stays sharp."),
      choice("replanning_method", &P::replanning_method, "footprint", namesOf(kReplanningMethods),
             S::kReplanning,
             "Remaining area for replanning: convex_hull, concave_hull (alpha shape) or "
             "footprint."),
      number("replanning_sliver_fraction", &P::replanning_sliver_fraction, "", 0.2,
             interval(0.0, false, 1.0, true), S::kReplanning,
             "Remaining strips narrower than this share of the sweep spacing are removed."),
      number("replanning_min_area", &P::replanning_min_area, "m^2", 1.0, nonNegative(),
             S::kReplanning,
             "Remaining parts smaller than this are dropped, each named in a warning."),
      number("replanning_simplify_tolerance", &P::replanning_simplify_tolerance, "m", 0.1,
             nonNegative(), S::kReplanning,
             "Remaining-area boundaries are simplified within this distance."),
      number("alpha", &P::alpha, "m", 2.0, positive(), S::kReplanning,
             "Alpha-shape parameter of replanning_method concave_hull."),
  };
}

/// Where the dynamic vehicle's values come from.
constexpr const char* kBlueRov =
    "a BlueROV2, identified by C.-J. Wu, 6-DoF Modelling and Control of a Remotely Operated "
    "Vehicle, MSc thesis, Flinders University, 2018 (also von Benzon et al., J. Mar. Sci. "
    "Eng. 10:1898, 2022)";
/// How the speed loops' bandwidths were chosen.
constexpr const char* kLoopGains =
    "the cascade rule (an inner loop several times faster than the outer one: 5 > 3 x "
    "position_gain, 10 = 2 x yaw_gain) up to the fastest a controller at 1 / sim_dt Hz runs "
    "without overshoot";
/// The model of the disturbances.
constexpr const char* kGaussMarkov =
    "a first-order Gauss-Markov process per axis (Fossen, Handbook of Marine Craft "
    "Hydrodynamics and Motion Control, 2011, Section 8.3)";

/// The robot model of `coverage_tool simulate` and the auv_simulator node: the dynamic vehicle.
std::vector<ParameterDeclaration> vehicleBodyDeclarations() {
  using S = ParameterStage;
  return {
      choice("vehicle_model", &P::vehicle_model, "dynamic", namesOf(kVehicleModels), S::kSimulation,
             "The robot model of simulate and auv_simulator: dynamic (a rigid body in surge, "
             "sway and yaw with inertia, added mass, damping and thruster limits: the "
             "parameters from mass to yaw_rate_loop_gain) or kinematic (speed and yaw rate "
             "follow their commands at once)."),
      number("mass", &P::mass, "kg", 11.5, positive(), S::kSimulation, "Dynamic vehicle: dry mass.",
             kBlueRov),
      number("added_mass_surge", &P::added_mass_surge, "kg", 5.5, nonNegative(), S::kSimulation,
             "Dynamic vehicle: added mass in surge (-X_u').", kBlueRov),
      number("added_mass_sway", &P::added_mass_sway, "kg", 12.7, nonNegative(), S::kSimulation,
             "Dynamic vehicle: added mass in sway (-Y_v').", kBlueRov),
      number("inertia_yaw", &P::inertia_yaw, "kg m^2", 0.16, positive(), S::kSimulation,
             "Dynamic vehicle: moment of inertia about the vertical axis.", kBlueRov),
      number("added_inertia_yaw", &P::added_inertia_yaw, "kg m^2", 0.12, nonNegative(),
             S::kSimulation, "Dynamic vehicle: added inertia in yaw (-N_r').", kBlueRov),
      number("damping_surge_linear", &P::damping_surge_linear, "N s/m", 4.03, nonNegative(),
             S::kSimulation, "Dynamic vehicle: linear damping in surge (-X_u).", kBlueRov),
      number("damping_sway_linear", &P::damping_sway_linear, "N s/m", 6.22, nonNegative(),
             S::kSimulation, "Dynamic vehicle: linear damping in sway (-Y_v).", kBlueRov),
      number("damping_yaw_linear", &P::damping_yaw_linear, "N m s/rad", 0.07, nonNegative(),
             S::kSimulation, "Dynamic vehicle: linear damping in yaw (-N_r).", kBlueRov),
      number("damping_surge_quadratic", &P::damping_surge_quadratic, "N s^2/m^2", 18.18,
             nonNegative(), S::kSimulation, "Dynamic vehicle: quadratic damping in surge.",
             kBlueRov),
      number("damping_sway_quadratic", &P::damping_sway_quadratic, "N s^2/m^2", 21.66,
             nonNegative(), S::kSimulation, "Dynamic vehicle: quadratic damping in sway.",
             kBlueRov),
      number("damping_yaw_quadratic", &P::damping_yaw_quadratic, "N m s^2/rad^2", 1.55,
             nonNegative(), S::kSimulation, "Dynamic vehicle: quadratic damping in yaw.", kBlueRov),
      number("thrust_max", &P::thrust_max, "N", 113.0, positive(), S::kSimulation,
             "Dynamic vehicle: largest surge force.",
             "four T200 thrusters at 40 N (their reverse thrust at 16 V, Blue Robotics data "
             "sheet) on a 45 degree vectored frame: 4 x 40 x cos 45"),
      number("yaw_torque_max", &P::yaw_torque_max, "N m", 30.0, positive(), S::kSimulation,
             "Dynamic vehicle: largest yaw torque.",
             "the same thrusters on a 0.189 m lever arm: 4 x 40 x 0.189"),
      flag("sway_actuated", &P::sway_actuated, true, S::kSimulation,
           "Dynamic vehicle: true, the four vectored thrusters drive surge, sway and yaw, "
           "sharing their limits (a sway force up to thrust_max; a demand beyond the "
           "thrusters is scaled down whole); false, a torpedo-like variant whose sway is not "
           "actuated (surge and yaw limited apart).",
           "the BlueROV2's vectored frame, whose four horizontal thrusters at 45 degrees drive "
           "sway as they drive surge (Wu 2018; Blue Robotics, BlueROV2 vectored frame)"),
      number("surge_loop_gain", &P::surge_loop_gain, "1/s", 5.0, loopGain(), S::kSimulation,
             "Dynamic vehicle: bandwidth of the speed loop that turns the surge speed command "
             "into force.",
             kLoopGains),
      number("yaw_rate_loop_gain", &P::yaw_rate_loop_gain, "1/s", 10.0, loopGain(), S::kSimulation,
             "Dynamic vehicle: bandwidth of the loop that turns the yaw rate command into "
             "torque.",
             kLoopGains),
  };
}

/// The robot model's controllers, disturbances and simulation.
std::vector<ParameterDeclaration> controllerDeclarations() {
  using S = ParameterStage;
  NumberRange time_limit = positive();
  time_limit.quotient_parameter = "sim_dt";
  time_limit.quotient_max = static_cast<double>(RobotSimulator::kMaxSteps);
  NumberRange seed = interval(0.0, false, 4294967295.0, false);
  seed.integer = true;
  NumberRange natural_frequency = positive();
  natural_frequency.product_parameter = "sim_dt";
  natural_frequency.product_max = 0.5;
  return {
      choice("controller", &P::controller, "timed", namesOf(kTrackingControllers), S::kSimulation,
             "How the simulated robot tracks the trajectory: timed (feedforward of the "
             "reference's acceleration and damping plus PD on the reference p_d(t) of the "
             "trajectory's t column, per axis; chosen on principle: the planner's output is a "
             "timed trajectory, and this is how such a reference is tracked, Fossen 2021, Ch. "
             "12), setpoint (the first follower, homing on each pose in turn), pose_stream (as "
             "timed, pose i released at i / pose_rate) or los (line-of-sight guidance on the "
             "pose polyline with look-ahead los_lookahead, Fossen 2021, Ch. 12)."),
      flag("braking", &P::braking, true, S::kSimulation,
           "setpoint only: brake in time (speed at most sqrt(2 a_max d)) to stop where the "
           "trajectory turns in place; false is a plain P controller, as the thesis's.",
           "the setpoint follower's fix of its late braking (docs/EXPERIMENTS.md)"),
      number("tracking_natural_frequency", &P::tracking_natural_frequency, "rad/s", 1.0,
             natural_frequency, S::kSimulation,
             "timed and pose_stream: natural frequency wn of the PD tracking loop (Kp = M wn^2, "
             "Kd = 2 zeta wn M per axis).",
             "a bandwidth below the vehicle's velocity loops (surge 5 1/s, yaw rate 10 1/s) by "
             "the cascade rule; wn * sim_dt <= 0.5 keeps the discrete loop stable"),
      number("tracking_damping", &P::tracking_damping, "", 1.0, positive(), S::kSimulation,
             "timed and pose_stream: damping ratio zeta of the PD tracking loop.",
             "critical damping: the fastest response without overshoot (Fossen 2021, Ch. 12, "
             "pole placement)"),
      number("pose_rate", &P::pose_rate, "Hz", 1.0, positive(), S::kSimulation,
             "pose_stream only: poses released per second (pose i at i / pose_rate).",
             "a waypoint stream of one pose a second, the rate of a vehicle's mission link"),
      number("los_lookahead", &P::los_lookahead, "m", 0.0, nonNegative(), S::kSimulation,
             "los only: look-ahead distance along the pose polyline; 0: the turning radius.",
             "a look-ahead of the order of the path's radius of curvature (Fossen 2021, Ch. "
             "12, lookahead-based steering)"),
      number("yaw_gain", &P::yaw_gain, "1/s", 5.0, loopGain(), S::kSimulation,
             "Yaw-rate command per rad of heading error (then limited to yaw_rate_max)."),
      number("position_gain", &P::position_gain, "1/s", 1.5, positive(), S::kSimulation,
             "Surge-speed command per m of distance to the current target pose (then limited "
             "to v_max)."),
      number("position_tolerance", &P::position_tolerance, "m", 0.05, positive(), S::kSimulation,
             "A target pose counts as reached within this distance (or once "
             "passed)."),
      number("yaw_tolerance", &P::yaw_tolerance, "rad", 0.05, interval(0.0, true, M_PI, true),
             S::kSimulation,
             "The target of an in-place rotation counts as reached within this heading "
             "error."),
      number("current_x", &P::current_x, "m/s", 0.0, NumberRange{}, S::kSimulation,
             "Constant water current that carries the robot, along x."),
      number("current_y", &P::current_y, "m/s", 0.0, NumberRange{}, S::kSimulation,
             "Constant water current that carries the robot, along y."),
      number("current_sigma", &P::current_sigma, "m/s", 0.0, nonNegative(), S::kSimulation,
             "Standard deviation of the current's fluctuation about (current_x, current_y), "
             "per axis, unknown to the controller; 0: none.",
             "lake currents are of the order of a few cm/s (Wuest and Lorke, Annu. Rev. Fluid "
             "Mech. 35:373, 2003); the fluctuation is a first-order Gauss-Markov process"),
      number("current_time_constant", &P::current_time_constant, "s", 60.0, positive(),
             S::kSimulation, "Correlation time of the current's fluctuation.", kGaussMarkov),
      number("navigation_sigma", &P::navigation_sigma, "m", 0.0, nonNegative(), S::kSimulation,
             "Standard deviation of the navigation solution's position error, per axis; the "
             "controller steers by the true position plus this error; 0: none.",
             "an acoustic short-baseline system such as the Water Linked Underwater GPS is "
             "good to about 1 % of its range, 0.1 m at 10 m"),
      number("navigation_time_constant", &P::navigation_time_constant, "s", 2.0, positive(),
             S::kSimulation,
             "Correlation time of the navigation error (fixes at a few Hz, filtered).",
             kGaussMarkov),
      number("disturbance_seed", &P::disturbance_seed, "", 1.0, seed, S::kSimulation,
             "Which draw of the disturbances a run meets, so that a run repeats exactly."),
      number("sim_dt", &P::sim_dt, "s", 0.1, positive(), S::kSimulation, "Simulation time step."),
      number("sim_time_limit", &P::sim_time_limit, "s", 36000.0, time_limit, S::kSimulation,
             "Simulated time after which a run that has not reached the last pose gives up."),
  };
}

/// Every declaration, in the order of config/default.yaml.
std::vector<ParameterDeclaration> allDeclarations() {
  std::vector<ParameterDeclaration> all = planningDeclarations();
  for (auto* part : {sensingDeclarations, trajectoryDeclarations, vehicleBodyDeclarations,
                     controllerDeclarations}) {
    for (ParameterDeclaration& declaration : part()) all.push_back(std::move(declaration));
  }
  return all;
}

/// `text` as code: in backticks for markdown.
std::string code(const std::string& text, bool markdown) {
  return markdown ? "`" + text + "`" : text;
}

/// A range's end as the reference writes it ("pi" for pi).
std::string boundText(double value) { return value == M_PI ? "pi" : formatNumber(value); }

/// The numbers' part of validValuesText; with `parameters`, bounds by other parameters
/// name their values ("turning_radius = 1").
std::string numberRangeText(const ParameterDeclaration& d, bool markdown,
                            const PlannerParameters* parameters, bool with_unit = false) {
  const NumberRange& r = d.range;
  const auto bound = [&](const char* name) {
    std::string text = code(name, markdown);
    if (parameters != nullptr) {
      text += " = " + parameterValueText(*findParameter(name),
                                         parameterValue(*parameters, *findParameter(name)));
    }
    return text;
  };
  const bool has_upper = std::isfinite(r.upper) || r.upper_parameter != nullptr;
  std::string text;
  if (r.lower_parameter != nullptr) {
    text = ">= " + bound(r.lower_parameter);
  } else if (has_upper && std::isfinite(r.lower)) {
    text = std::string(r.lower_open ? "(" : "[") + boundText(r.lower) + ", " +
           (r.upper_parameter != nullptr ? bound(r.upper_parameter) : boundText(r.upper)) +
           (r.upper_open ? ")" : "]");
    if (r.integer) text = "an integer in " + text;
  } else if (std::isfinite(r.lower)) {
    text = std::string(r.lower_open ? "> " : ">= ") + boundText(r.lower);
  } else {
    text = "finite";
  }
  if (r.zero_allowed) text = "0 or " + text;
  if (with_unit && d.unit[0] != '\0') text += " (" + std::string(d.unit) + ")";
  for (const auto& [other, operation, limit] :
       {std::tuple{r.product_parameter, " * ", r.product_max},
        std::tuple{r.quotient_parameter, " / ", r.quotient_max}}) {
    if (other == nullptr) continue;
    text += ", and " + code(std::string(d.name) + operation + other, markdown) +
            " <= " + formatNumber(limit);
    if (parameters != nullptr) text += " (" + bound(other) + ")";
  }
  if (d.word != nullptr) text += ", or the word " + code(d.word, markdown);
  if (r.unchecked_while_zero != nullptr) {
    text += "; ignored when " + code(r.unchecked_while_zero, markdown) + " is 0";
  }
  return text;
}

/// The value of the number parameter `name`.
double numberOf(const PlannerParameters& parameters, const char* name) {
  return parameters.*std::get<double P::*>(findParameter(name)->member);
}

/// Whether `value` lies in `d`'s range; the bounds by other parameters only with
/// `parameters`.
bool inRange(const ParameterDeclaration& d, double value, const PlannerParameters* parameters) {
  const NumberRange& r = d.range;
  if (!std::isfinite(value)) return false;
  if (r.zero_allowed && value == 0.0) return true;
  if (r.integer && value != std::floor(value)) return false;
  if (r.lower_open ? !(value > r.lower) : !(value >= r.lower)) return false;
  if (r.upper_open ? !(value < r.upper) : !(value <= r.upper)) return false;
  if (parameters == nullptr) return true;
  if (r.upper_parameter != nullptr && value > numberOf(*parameters, r.upper_parameter)) {
    return false;
  }
  if (r.lower_parameter != nullptr && value < numberOf(*parameters, r.lower_parameter)) {
    return false;
  }
  if (r.product_parameter != nullptr &&
      value * numberOf(*parameters, r.product_parameter) > r.product_max) {
    return false;
  }
  return r.quotient_parameter == nullptr ||
         value / numberOf(*parameters, r.quotient_parameter) <= r.quotient_max;
}

/// Where the value of `d`, or else of a parameter bounding it, came from; "" for defaults.
std::string originOf(const ParameterDeclaration& d, const ParameterOrigins& origins) {
  const NumberRange& r = d.range;
  for (const char* name :
       {d.name, r.upper_parameter, r.lower_parameter, r.product_parameter, r.quotient_parameter}) {
    if (name == nullptr) continue;
    const auto origin = origins.find(name);
    if (origin != origins.end()) return origin->second;
  }
  return "";
}

/// Throws the InvalidInputError of `value` out of `d`'s range, naming its origin.
[[noreturn]] void outOfRange(const ParameterDeclaration& d, const ParameterValue& value,
                             const std::string& origin, const PlannerParameters* parameters) {
  std::string must;
  if (!d.choices.empty()) {
    must = "one of: ";
    for (std::size_t i = 0; i < d.choices.size(); ++i) {
      must += (i == 0 ? "" : ", ") + d.choices[i];
    }
    throw InvalidInputError((origin.empty() ? "" : origin + ": ") + d.name + " = '" +
                            std::get<std::string>(value) + "' is not " + must);
  }
  must = numberRangeText(d, false, parameters, true);
  if (must.rfind("finite", 0) == 0) must = "a finite number" + must.substr(6);
  if (must.front() == '>') must = "a finite number " + must;
  if (must.front() == '(' || must.front() == '[') must = "in " + must;
  throw InvalidInputError((origin.empty() ? "" : origin + ": ") + d.name + " = " +
                          formatNumber(std::get<double>(value)) + " is out of range: it must be " +
                          must);
}

/// Whether `name` is one of the names `d` allows.
bool isChoice(const ParameterDeclaration& d, const std::string& name) {
  return std::find(d.choices.begin(), d.choices.end(), name) != d.choices.end();
}

/// The type of a value, as a message names it.
std::string kindOf(const ParameterValue& value) {
  if (const double* number = std::get_if<double>(&value)) return formatNumber(*number);
  if (const bool* on = std::get_if<bool>(&value)) return *on ? "true" : "false";
  return "'" + std::get<std::string>(value) + "'";
}

/// `text` as YAML comment lines of at most kCommentWidth characters.
void wrapComment(std::ostringstream& out, const std::string& text) {
  std::istringstream words(text);
  std::string word, line = "#";
  while (words >> word) {
    if (line.size() + 1 + word.size() > kCommentWidth) {
      out << line << "\n";
      line = "#";
    }
    line += " " + word;
  }
  out << line << "\n";
}

}  // namespace

const char* stageName(ParameterStage stage) {
  static constexpr std::array<const char*, 10> kNames = {
      "decomposition", "route",     "vehicle",    "wall offset", "sensor",
      "repair",        "smoothing", "trajectory", "replanning",  "simulation"};
  return kNames.at(static_cast<std::size_t>(stage));
}

PlannerParameters::PlannerParameters() {
  for (const ParameterDeclaration& declaration : parameterSchema()) {
    std::visit(
        [this](auto member, const auto& value) {
          using Field = std::decay_t<decltype(this->*member)>;
          if constexpr (std::is_same_v<Field, std::decay_t<decltype(value)>>) {
            this->*member = value;
          }
        },
        declaration.member, declaration.default_value);
  }
}

const std::vector<ParameterDeclaration>& parameterSchema() {
  static const std::vector<ParameterDeclaration> schema = allDeclarations();
  return schema;
}

const ParameterDeclaration* findParameter(std::string_view name) {
  for (const ParameterDeclaration& declaration : parameterSchema()) {
    if (name == declaration.name) return &declaration;
  }
  return nullptr;
}

std::string validValuesText(const ParameterDeclaration& declaration, bool markdown) {
  if (std::holds_alternative<bool P::*>(declaration.member)) return "boolean";
  if (!declaration.choices.empty()) {
    std::string text;
    for (const std::string& name : declaration.choices) {
      text += (text.empty() ? "" : ", ") + code(name, markdown);
    }
    return text;
  }
  return numberRangeText(declaration, markdown, nullptr);
}

std::string parameterValueText(const ParameterDeclaration& declaration,
                               const ParameterValue& value) {
  if (const double* number = std::get_if<double>(&value)) {
    if (declaration.word != nullptr && *number == kClearanceOfWallDistance) {
      return declaration.word;
    }
    return formatRoundTrip(*number);
  }
  if (const bool* on = std::get_if<bool>(&value)) return *on ? "true" : "false";
  return std::get<std::string>(value);
}

ParameterValue parameterValue(const PlannerParameters& parameters,
                              const ParameterDeclaration& declaration) {
  return std::visit([&parameters](auto member) { return ParameterValue(parameters.*member); },
                    declaration.member);
}

void assignParameter(PlannerParameters& parameters, const ParameterDeclaration& declaration,
                     const ParameterValue& value, const std::string& origin) {
  const std::string prefix = (origin.empty() ? "" : origin + ": ") + declaration.name;
  if (auto number_member = std::get_if<double P::*>(&declaration.member)) {
    if (const std::string* text = std::get_if<std::string>(&value)) {
      if (declaration.word != nullptr && *text == declaration.word) {
        parameters.*(*number_member) = kClearanceOfWallDistance;
        return;
      }
      throw InvalidInputError(prefix + ": the value " + kindOf(value) + " is not a number" +
                              (declaration.word != nullptr
                                   ? std::string(" or the word ") + declaration.word
                                   : std::string()));
    }
    if (!std::holds_alternative<double>(value)) {
      throw InvalidInputError(prefix + ": the value " + kindOf(value) + " is not a number");
    }
    const double number = std::get<double>(value);
    // A number equal to the word's stand-in would read as the word.
    const bool reads_as_word = declaration.word != nullptr && number == kClearanceOfWallDistance;
    if (reads_as_word || (declaration.range.unchecked_while_zero == nullptr &&
                          !inRange(declaration, number, nullptr))) {
      outOfRange(declaration, value, origin, nullptr);
    }
    parameters.*(*number_member) = number;
  } else if (auto flag_member = std::get_if<bool P::*>(&declaration.member)) {
    if (!std::holds_alternative<bool>(value)) {
      throw InvalidInputError(prefix + ": the value " + kindOf(value) + " is not true or false");
    }
    parameters.*(*flag_member) = std::get<bool>(value);
  } else {
    const std::string* name = std::get_if<std::string>(&value);
    if (name == nullptr) {
      throw InvalidInputError(prefix + ": the value " + kindOf(value) + " is not a name");
    }
    if (!isChoice(declaration, *name)) outOfRange(declaration, value, origin, nullptr);
    parameters.*std::get<std::string P::*>(declaration.member) = *name;
  }
}

void checkParameters(const PlannerParameters& parameters, const ParameterOrigins& origins) {
  for (const ParameterDeclaration& declaration : parameterSchema()) {
    const ParameterValue value = parameterValue(parameters, declaration);
    const std::string where = originOf(declaration, origins);
    if (const std::string* name = std::get_if<std::string>(&value)) {
      if (!isChoice(declaration, *name)) outOfRange(declaration, value, where, nullptr);
    } else if (const double* number = std::get_if<double>(&value)) {
      const bool stand_in = declaration.word != nullptr && *number == kClearanceOfWallDistance;
      const char* unchecked = declaration.range.unchecked_while_zero;
      if (stand_in || (unchecked != nullptr && numberOf(parameters, unchecked) == 0.0)) continue;
      if (!inRange(declaration, *number, &parameters)) {
        outOfRange(declaration, value, where, &parameters);
      }
    }
  }
}

std::string defaultParametersYaml() {
  std::ostringstream out;
  out << "# Default parameters (docs/REFERENCE.md, Parameters), generated from the parameter\n"
         "# schema (coverage_system/parameters/parameter_schema.cpp) by\n"
         "# `coverage_tool parameters`; a test asserts that this file equals its output. The\n"
         "# same names are the keys of mission files, of `coverage_tool --set name=value` and\n"
         "# of the nodes' private parameters.\n";
  for (const ParameterDeclaration& d : parameterSchema()) {
    std::string comment = d.description;
    comment += std::string(" Valid: ") + validValuesText(d, false);
    if (d.unit[0] != '\0') comment += std::string(" (") + d.unit + ")";
    comment += ".";
    if (d.source[0] != '\0') comment += std::string(" Source: ") + d.source + ".";
    out << "\n";
    wrapComment(out, comment);
    std::string value = parameterValueText(d, d.default_value);
    if (std::holds_alternative<double>(d.default_value) && !d.range.integer &&
        value.find_first_of(".e") == std::string::npos && d.word == nullptr) {
      value += ".0";
    }
    out << d.name << ": " << value << "\n";
  }
  return out.str();
}

}  // namespace kinematic_coverage::core
