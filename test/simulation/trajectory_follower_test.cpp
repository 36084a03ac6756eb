#include "trajectory_generation_tools/simulation/trajectory_follower.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "trajectory_generation_tools/simulation/line_of_sight_guidance.h"
#include "trajectory_generation_tools/simulation/pose_sequence_timing.h"
#include "trajectory_generation_tools/simulation/robot_simulator.h"

namespace kinematic_coverage::core {
namespace {

/// Poses every `spacing` m along the x axis from 0 to `length`, heading +x.
std::vector<Pose2> straightLine(double length, double spacing) {
  std::vector<Pose2> poses;
  const int pieces = static_cast<int>(std::ceil(length / spacing - 1e-9));
  for (int i = 0; i <= pieces; ++i) poses.push_back({length * i / pieces, 0.0, 0.0});
  return poses;
}

/// An in-place rotation at the origin from heading 0 to `angle`, one pose every `step` rad.
std::vector<Pose2> rotation(double angle, double step) {
  std::vector<Pose2> poses;
  const int pieces = static_cast<int>(std::ceil(angle / step - 1e-9));
  for (int i = 0; i <= pieces; ++i) poses.push_back({0.0, 0.0, angle * i / pieces});
  return poses;
}

/// The default parameters with `vehicle_model`.
PlannerParameters withVehicle(const std::string& vehicle_model) {
  PlannerParameters parameters;
  parameters.controller = "setpoint";
  parameters.vehicle_model = vehicle_model;
  return parameters;
}

/// Both vehicles, for the properties they share.
const std::vector<std::string> kVehicles{"dynamic", "kinematic"};

TEST(TrajectoryFollowerTest, FollowsAStraightLineWithZeroErrorInTheExpectedTime) {
  // position_gain * v_max <= a_max, so that the speed can follow the set-point controller's
  // command exactly: accelerate at a_max to v_max, cruise until position_gain times the
  // distance left falls below v_max, then approach exponentially to the tolerance.
  PlannerParameters parameters = withVehicle("kinematic");
  parameters.position_gain = 0.3;
  const double v = parameters.v_max;
  const double a = parameters.a_max;
  const double k = parameters.position_gain;
  const double length = 10.0;
  const double expected = v / a + (length - v * v / (2.0 * a) - v / k) / v +
                          std::log((v / k) / parameters.position_tolerance) / k;
  const SimulationResult result =
      RobotSimulator(robotModelOf(parameters)).simulate(straightLine(length, length));
  EXPECT_NEAR(result.traversal_time_s, expected, 0.01 * expected);
  // Zero up to the rounding of the distance to a segment.
  EXPECT_LT(result.tracking.sum_m, 1e-9);
  EXPECT_LT(result.tracking.percentiles_m.back(), 1e-12);
  const Pose2& end = result.steps.back().pose;
  EXPECT_NEAR(end.x, length, parameters.position_tolerance);
  EXPECT_EQ(end.y, 0.0);
  EXPECT_EQ(end.yaw, 0.0);
  // A step every sim_dt, the start first.
  ASSERT_GE(result.steps.size(), 2u);
  EXPECT_EQ(result.steps.front().t, 0.0);
  for (std::size_t i = 1; i < result.steps.size(); ++i) {
    EXPECT_NEAR(result.steps[i].t - result.steps[i - 1].t, parameters.sim_dt, 1e-9);
  }
  EXPECT_DOUBLE_EQ(result.steps.back().t, result.traversal_time_s);
}

TEST(TrajectoryFollowerTest, SlowsTowardsEveryPoseItIsHanded) {
  // The set-point controller slows towards each pose: the same line is followed exactly
  // whatever the sampling, but the denser it is sampled, the longer it takes.
  for (const std::string& vehicle : kVehicles) {
    const PlannerParameters parameters = withVehicle(vehicle);
    double previous_time = 0.0;
    for (const double spacing : {10.0, 0.5, 0.1}) {
      const SimulationResult result =
          RobotSimulator(robotModelOf(parameters)).simulate(straightLine(10.0, spacing));
      EXPECT_LT(result.tracking.sum_m, 1e-9) << vehicle << " " << spacing;
      EXPECT_GT(result.traversal_time_s, previous_time) << vehicle << " " << spacing;
      previous_time = result.traversal_time_s;
    }
    // Never faster than v_max allows.
    EXPECT_GT(previous_time, 10.0 / parameters.v_max) << vehicle;
  }
}

TEST(TrajectoryFollowerTest, TheDynamicVehicleCruisesAtVMaxOnALongLine) {
  // The surge loop's feedforwards hold the reference once it settles: within 1 %, as the
  // force is held over a step while the damping changes with the speed.
  const PlannerParameters parameters = withVehicle("dynamic");
  const SimulationResult result =
      RobotSimulator(robotModelOf(parameters)).simulate(straightLine(40.0, 40.0));
  double fastest = 0.0;
  for (std::size_t i = 1; i < result.steps.size(); ++i) {
    const double speed =
        (result.steps[i].pose.position() - result.steps[i - 1].pose.position()).norm() /
        parameters.sim_dt;
    fastest = std::max(fastest, speed);
  }
  EXPECT_NEAR(fastest, parameters.v_max, 0.01 * parameters.v_max);
  EXPECT_LT(result.tracking.sum_m, 1e-9);
}

TEST(TrajectoryFollowerTest, TurnsInPlaceWhereTheTrajectoryRotates) {
  for (const std::string& vehicle : kVehicles) {
    const PlannerParameters parameters = withVehicle(vehicle);
    const SimulationResult result =
        RobotSimulator(robotModelOf(parameters)).simulate(rotation(M_PI / 2, 0.2));
    const Pose2& end = result.steps.back().pose;
    EXPECT_EQ(end.x, 0.0) << vehicle;
    EXPECT_EQ(end.y, 0.0) << vehicle;
    EXPECT_LE(std::abs(wrapAngle(end.yaw - M_PI / 2)), parameters.yaw_tolerance) << vehicle;
    EXPECT_LT(result.tracking.sum_m, 1e-9) << vehicle;
    EXPECT_GE(result.traversal_time_s,
              (M_PI / 2 - parameters.yaw_tolerance) / parameters.yaw_rate_max - 1e-9)
        << vehicle;
  }
}

TEST(TrajectoryFollowerTest, FinerRotationSamplingSlowsALowGainRobot) {
  // A low yaw gain approaches each rotation pose exponentially (Table 4.3's setting): more
  // poses on the same turn take longer. A high gain turns at the saturated yaw rate.
  for (const std::string& vehicle : kVehicles) {
    PlannerParameters low = withVehicle(vehicle);
    low.yaw_gain = 1.0;
    const double coarse =
        RobotSimulator(robotModelOf(low)).simulate(rotation(M_PI, 0.2)).traversal_time_s;
    const double fine =
        RobotSimulator(robotModelOf(low)).simulate(rotation(M_PI, 0.05)).traversal_time_s;
    EXPECT_GT(fine, 1.5 * coarse) << vehicle;
    PlannerParameters high = withVehicle(vehicle);
    high.yaw_gain = 5.0;
    const double fast =
        RobotSimulator(robotModelOf(high)).simulate(rotation(M_PI, 0.2)).traversal_time_s;
    EXPECT_LT(fast, coarse) << vehicle;
    EXPECT_LT(fast, 1.5 * M_PI / high.yaw_rate_max) << vehicle;
  }
}

/// An unsmoothed corner: 5 m along x, a turn in place to +y, 5 m along y.
std::vector<Pose2> unsmoothedCorner() {
  std::vector<Pose2> corner = straightLine(5.0, 0.5);
  for (const Pose2& turn : rotation(M_PI / 2, 0.2)) corner.push_back({5.0, 0.0, turn.yaw});
  for (int i = 1; i <= 10; ++i) corner.push_back({5.0, 0.5 * i, M_PI / 2});
  return corner;
}

TEST(TrajectoryFollowerTest, BrakesInTimeToTurnInPlaceAtACorner) {
  // The speed is held to what a_max can stop before the corner, so neither vehicle runs
  // past it (towards a wall, in a planned path) by more than the tolerance; the dynamic
  // vehicle may slide a few centimetres more while it turns, before its loops have stopped
  // it.
  for (const std::string& vehicle : kVehicles) {
    const PlannerParameters parameters = withVehicle(vehicle);
    const SimulationResult result =
        RobotSimulator(robotModelOf(parameters)).simulate(unsmoothedCorner());
    double furthest = 0.0;
    for (const SimulationStep& step : result.steps) furthest = std::max(furthest, step.pose.x);
    const double slide = vehicle == "dynamic" ? parameters.position_tolerance : 0.0;
    EXPECT_LE(furthest, 5.0 + parameters.position_tolerance + slide) << vehicle;
    EXPECT_LT(result.tracking_axes.x_max_m, parameters.position_tolerance + slide) << vehicle;
    // And it still runs near v_max between the corners (the set-point controller slows a
    // little towards each pose): braking starts v_max^2 / (2 a_max) before the stop.
    double fastest = 0.0;
    for (std::size_t i = 1; i < result.steps.size(); ++i) {
      fastest = std::max(
          fastest, (result.steps[i].pose.position() - result.steps[i - 1].pose.position()).norm() /
                       parameters.sim_dt);
    }
    EXPECT_GT(fastest, 0.85 * parameters.v_max) << vehicle;
  }
}

TEST(TrajectoryFollowerTest, WithoutBrakingItRunsPastTheCorner) {
  // braking: false is the plain P controller: the speed is not held to what a_max can stop,
  // so the kinematic robot runs past the corner by more than the tolerance.
  PlannerParameters parameters = withVehicle("kinematic");
  parameters.braking = false;
  const SimulationResult result =
      RobotSimulator(robotModelOf(parameters)).simulate(unsmoothedCorner());
  double furthest = 0.0;
  for (const SimulationStep& step : result.steps) furthest = std::max(furthest, step.pose.x);
  EXPECT_GT(furthest, 5.0 + parameters.position_tolerance);
}

TEST(TrajectoryFollowerTest, TheErrorsOfAStepAreConsistent) {
  // The axis parts make up the nearest-point error, and the target piece is never nearer
  // than the nearest point of the whole path.
  PlannerParameters parameters = withVehicle("dynamic");
  parameters.navigation_sigma = 0.1;
  const SimulationResult result =
      RobotSimulator(robotModelOf(parameters)).simulate(unsmoothedCorner());
  EXPECT_GT(result.tracking_axes.x_max_m, 0.01);
  EXPECT_GT(result.tracking_axes.y_max_m, 0.01);
  for (const SimulationStep& step : result.steps) {
    EXPECT_NEAR(std::hypot(step.tracking_error_x_m, step.tracking_error_y_m), step.tracking_error_m,
                1e-12);
    EXPECT_GE(step.target_error_m, step.tracking_error_m - 1e-12);
  }
}

TEST(TrajectoryFollowerTest, SteersByItsNavigationSolution) {
  // With a navigation error of standard deviation sigma per axis, the robot holds its
  // estimate on the line, so its true position strays from it by about that error: the
  // median cross-track error of a Gaussian is 0.67 sigma. It still arrives (by its
  // estimate), and the draw repeats for a seed.
  for (const std::string& vehicle : kVehicles) {
    PlannerParameters parameters = withVehicle(vehicle);
    parameters.navigation_sigma = 0.1;
    parameters.navigation_time_constant = 2.0;
    const std::vector<Pose2> line = straightLine(30.0, 0.5);
    const SimulationResult result = RobotSimulator(robotModelOf(parameters)).simulate(line);
    const double median = result.tracking.percentiles_m[4];
    EXPECT_GT(median, 0.3 * 0.67 * parameters.navigation_sigma) << vehicle;
    EXPECT_LT(median, 2.0 * 0.67 * parameters.navigation_sigma) << vehicle;
    EXPECT_LT(std::abs(result.steps.back().pose.x - 30.0), 5.0 * parameters.navigation_sigma)
        << vehicle;
    const SimulationResult again = RobotSimulator(robotModelOf(parameters)).simulate(line);
    EXPECT_EQ(again.traversal_time_s, result.traversal_time_s) << vehicle;
    EXPECT_EQ(again.tracking.sum_m, result.tracking.sum_m) << vehicle;
    parameters.disturbance_seed = 2.0;
    const SimulationResult other = RobotSimulator(robotModelOf(parameters)).simulate(line);
    EXPECT_NE(other.tracking.sum_m, result.tracking.sum_m) << vehicle;
  }
}

TEST(TrajectoryFollowerTest, AHandedOnLakeRunsOnAcrossTrajectories) {
  // A robot handed a new trajectory mid-mission meets the lake's disturbances where they
  // had got to, as one uninterrupted lake would give them, not the seed's first draws.
  PlannerParameters parameters = withVehicle("dynamic");
  parameters.current_sigma = 0.02;
  parameters.navigation_sigma = 0.1;
  const RobotModel model = robotModelOf(parameters);
  const std::vector<Pose2> line = straightLine(30.0, 0.5);
  RobotState start;
  start.pose = line.front();
  TrajectoryFollower first(model, line, start);
  constexpr int kSteps = 200;
  for (int i = 0; i < kSteps; ++i) first.step();
  const std::vector<Pose2> rest(line.begin() + 10, line.end());
  TrajectoryFollower second(model, rest, first.state(), first.disturbance());
  TrajectoryFollower restarted(model, rest, first.state());
  EnvironmentDisturbance uninterrupted(model.disturbance, model.current_x, model.current_y);
  for (int i = 0; i < kSteps; ++i) uninterrupted.advance(model.sim_dt);
  for (int i = 0; i < 50; ++i) {
    EXPECT_EQ(second.disturbance().navigationError(), uninterrupted.navigationError()) << i;
    EXPECT_EQ(second.disturbance().current(), uninterrupted.current()) << i;
    const Point2 error = second.estimatedPose().position() - second.state().pose.position();
    EXPECT_NEAR((error - uninterrupted.navigationError()).norm(), 0.0, 1e-12) << i;
    second.step();
    restarted.step();
    uninterrupted.advance(model.sim_dt);
  }
  EXPECT_NE(restarted.disturbance().navigationError(), second.disturbance().navigationError());
}

TEST(TrajectoryFollowerTest, AFluctuatingCurrentPushesTheRobotOffItsLine) {
  // The controller knows the mean current (0 here), not its fluctuation: the robot is
  // pushed off the line until its position controller steers back, and still arrives.
  for (const std::string& vehicle : kVehicles) {
    PlannerParameters calm = withVehicle(vehicle);
    const std::vector<Pose2> line = straightLine(30.0, 0.5);
    const SimulationResult still = RobotSimulator(robotModelOf(calm)).simulate(line);
    PlannerParameters gusty = calm;
    gusty.current_sigma = 0.05;
    gusty.current_time_constant = 20.0;
    const SimulationResult pushed = RobotSimulator(robotModelOf(gusty)).simulate(line);
    EXPECT_LT(still.tracking.sum_m, 1e-9) << vehicle;
    EXPECT_GT(pushed.tracking.mean_m, 1e-3) << vehicle;
    EXPECT_LT(pushed.tracking.percentiles_m.back(), 0.5) << vehicle;
    EXPECT_NEAR(pushed.steps.back().pose.x, 30.0, calm.position_tolerance + 0.5) << vehicle;
  }
}

/// A quarter circle of radius 1 m sampled every 0.1 m, as the thesis's arcs are.
std::vector<Pose2> quarterCircle() {
  std::vector<Pose2> arc;
  for (int i = 0; i <= 16; ++i) {
    const double angle = M_PI / 2 * i / 16.0;
    arc.push_back({std::sin(angle), 1.0 - std::cos(angle), angle});
  }
  return arc;
}

/// The largest sway speed (m/s) through the water, with its sign, while following `arc`.
double mostSway(const PlannerParameters& parameters, const std::vector<Pose2>& arc) {
  RobotState start;
  start.pose = arc.front();
  TrajectoryFollower follower(robotModelOf(parameters), arc, start);
  double most_sway = 0.0;
  while (!follower.finished()) {
    follower.step();
    if (std::abs(follower.state().sway) > std::abs(most_sway)) most_sway = follower.state().sway;
  }
  return most_sway;
}

TEST(TrajectoryFollowerTest, TheTorpedoVariantSlipsOutwardsOnAnArc) {
  // Without sway actuation, the body slips to the right in a left turn, and the robot ends
  // up off the arc.
  PlannerParameters torpedo = withVehicle("dynamic");
  torpedo.sway_actuated = false;
  const std::vector<Pose2> arc = quarterCircle();
  EXPECT_LT(mostSway(torpedo, arc), -1e-4);
  const SimulationResult result = RobotSimulator(robotModelOf(torpedo)).simulate(arc);
  EXPECT_GT(result.tracking.mean_m, 1e-4);
  EXPECT_LT(result.tracking.percentiles_m.back(), 0.2);
}

TEST(TrajectoryFollowerTest, TheSwayLoopHoldsTheVectoredVehicleOffSlipping) {
  // With sway actuated (the default), the sway loop feeds the Coriolis force forward: the
  // sway speed through the water stays within a hundredth of the speed limit.
  const PlannerParameters vectored = withVehicle("dynamic");
  ASSERT_TRUE(vectored.sway_actuated);
  EXPECT_LT(std::abs(mostSway(vectored, quarterCircle())), 1e-2 * vectored.v_max);
}

TEST(TrajectoryFollowerTest, CrabsIntoACrossCurrentAndStillArrives) {
  for (const std::string& vehicle : kVehicles) {
    PlannerParameters parameters = withVehicle(vehicle);
    parameters.current_y = 0.1;
    const SimulationResult result =
        RobotSimulator(robotModelOf(parameters)).simulate(straightLine(20.0, 0.5));
    EXPECT_NEAR(result.steps.back().pose.x, 20.0, 0.5) << vehicle;
    EXPECT_GT(result.tracking.mean_m, 0.0) << vehicle;
    EXPECT_LT(result.tracking.percentiles_m.back(), 0.5) << vehicle;
    // Mid-way it heads upstream (yaw < 0) to hold the line against the current.
    const Pose2& middle = result.steps[result.steps.size() / 2].pose;
    EXPECT_LT(middle.yaw, -0.1) << vehicle;
    EXPECT_LT(std::abs(middle.y), 0.3) << vehicle;
  }
}

TEST(TrajectoryFollowerTest, GivesUpWhenTheCurrentIsFasterThanTheRobot) {
  for (const std::string& vehicle : kVehicles) {
    PlannerParameters parameters = withVehicle(vehicle);
    parameters.current_x = -1.0;
    parameters.sim_time_limit = 100.0;
    try {
      RobotSimulator(robotModelOf(parameters)).simulate(straightLine(10.0, 0.5));
      FAIL() << "expected InvalidInputError";
    } catch (const InvalidInputError& error) {
      EXPECT_NE(std::string(error.what())
                    .find("did not reach the last pose within sim_time_limit = 100 s (it was "
                          "driving to pose 2 of 21)"),
                std::string::npos)
          << vehicle << ": " << error.what();
    }
  }
}

TEST(TrajectoryFollowerTest, RestartsFromAMovingStateAndSkipsPassedPoses) {
  // As auv_simulator does when a new trajectory arrives: the robot keeps its pose and
  // velocities, and poses behind it count as passed.
  for (const std::string& vehicle : kVehicles) {
    const PlannerParameters parameters = withVehicle(vehicle);
    RobotState start;
    start.t = 42.0;
    start.pose = {5.2, 0.0, 0.0};
    start.speed = 0.3;
    TrajectoryFollower follower(robotModelOf(parameters), straightLine(10.0, 1.0), start);
    EXPECT_EQ(follower.nextTarget(), 6u) << vehicle;
    follower.step();
    EXPECT_DOUBLE_EQ(follower.state().t, 42.0 + parameters.sim_dt) << vehicle;
    EXPECT_GE(follower.state().speed, 0.3 - parameters.a_max * parameters.sim_dt - 1e-12)
        << vehicle;
    EXPECT_GT(follower.state().pose.x, 5.2) << vehicle;
    while (!follower.finished()) follower.step();
    EXPECT_EQ(follower.nextTarget(), follower.targets().size()) << vehicle;
    const double end_time = follower.state().t;
    follower.step();
    EXPECT_EQ(follower.state().t, end_time) << vehicle;
  }
}

TEST(TrajectoryFollowerTest, RejectsInvalidInput) {
  const PlannerParameters parameters;
  const RobotState start;
  EXPECT_THROW(TrajectoryFollower(robotModelOf(parameters), {}, start), InvalidInputError);
  EXPECT_THROW(
      TrajectoryFollower(robotModelOf(parameters), {{0, 0, 0}, {1, std::nan(""), 0}}, start),
      InvalidInputError);
  RobotState spinning;
  spinning.yaw_rate = std::nan("");
  EXPECT_THROW(TrajectoryFollower(robotModelOf(parameters), {{0, 0, 0}}, spinning),
               InvalidInputError);
  PlannerParameters too_high_gain;
  too_high_gain.yaw_gain = 20.0;
  EXPECT_THROW(TrajectoryFollower(robotModelOf(too_high_gain), {{0, 0, 0}}, start),
               InvalidInputError);
  PlannerParameters too_long;
  too_long.sim_time_limit = 1e9;
  EXPECT_THROW(RobotSimulator{robotModelOf(too_long)}, InvalidInputError);
  EXPECT_THROW(RobotSimulator(robotModelOf(parameters)).simulate({}), InvalidInputError);
}

/// A robot model of the dynamic, vectored vehicle with the timed controller, in calm water.
RobotModel timedModel(double sim_dt) {
  PlannerParameters parameters;
  parameters.controller = "timed";
  parameters.sim_dt = sim_dt;
  return robotModelOf(parameters);
}

TEST(TrajectoryFollowerTest, TheTimedControllerHasNoSteadyErrorOnAConstantVelocityReference) {
  // A straight line at 0.3 m/s, a pose every 0.1 s: once the start's transient has died
  // away, the feedforward carries the robot on the reference with no error left.
  std::vector<Pose2> poses;
  std::vector<double> times;
  for (int k = 0; k <= 600; ++k) {
    poses.push_back({0.03 * k, 0.0, 0.0});
    times.push_back(0.1 * k);
  }
  const TimedReference reference(poses, times);
  TrajectoryFollower follower(timedModel(0.1), poses, RobotState{}, times);
  double largest_late_error = 0.0;
  while (!follower.finished() && follower.state().t < 50.0) {
    follower.step();
    if (follower.state().t > 30.0) {
      largest_late_error = std::max(
          largest_late_error,
          (follower.state().pose.position() - reference.at(follower.state().t).position).norm());
    }
  }
  EXPECT_LT(largest_late_error, 1e-6);
}

TEST(TrajectoryFollowerTest, TheTimedControllerHasTheAnalyticStepResponse) {
  // A robot a small step e0 ahead of a resting reference: the PD law with the damping fed
  // forward at the reference velocity (zero) leaves the body's own linear damping d in the
  // loop, m e'' + (Kd + d) e' + Kp e = 0, whose solution from rest is
  // e0 (l2 e^(l1 t) - l1 e^(l2 t)) / (l2 - l1) with l1, l2 = -wn (z +- sqrt(z^2 - 1)) and
  // z = zeta + d / (2 m wn). The step is small enough that the quadratic damping is a
  // percent of the linear; the step is 0.01 s.
  RobotModel model = timedModel(0.01);
  model.position_tolerance = 1e-6;  // so that the run goes on until the step has died away
  const RigidBodyParameters& body = model.body;
  const double wn = model.tracking_natural_frequency;
  const double z =
      model.tracking_damping + body.damping_surge_linear / (2.0 * body.surgeInertia() * wn);
  ASSERT_GT(z, 1.0);
  const double l1 = -wn * (z - std::sqrt(z * z - 1.0));
  const double l2 = -wn * (z + std::sqrt(z * z - 1.0));
  const double e0 = 0.01;
  RobotState start;
  start.pose = {e0, 0.0, 0.0};
  TrajectoryFollower follower(model, {{0.0, 0.0, 0.0}}, start, {0.0});
  for (const double t : {1.0, 2.0, 4.0}) {
    while (!follower.finished() && follower.state().t < t - 1e-9) follower.step();
    ASSERT_FALSE(follower.finished()) << t;
    const double expected = e0 * (l2 * std::exp(l1 * t) - l1 * std::exp(l2 * t)) / (l2 - l1);
    EXPECT_NEAR(follower.state().pose.x, expected, 0.03 * e0) << t;
    EXPECT_NEAR(follower.state().pose.y, 0.0, 1e-12) << t;
  }
}

TEST(TrajectoryFollowerTest, TheTimedControllerNeedsTheTrajectorysTimes) {
  EXPECT_THROW(TrajectoryFollower(timedModel(0.1), {{0.0, 0.0, 0.0}}, RobotState{}),
               InvalidInputError);
}

/// A robot at rest at `pose`.
RobotState restingAt(const Pose2& pose) {
  RobotState state;
  state.pose = pose;
  return state;
}

TEST(TrajectoryFollowerTest, BrakingKeepsTheSpeedWithinWhatStopsTheRobotAtTheCorner) {
  // With braking, the setpoint and los controllers keep the surge speed at most
  // sqrt(2 a_max d), d the distance left to the corner where the trajectory turns in place,
  // up to a step: the speed is commanded from d at the step's start (at most v_max sim_dt
  // more than at its end) and its reference changes by at most a_max sim_dt a step.
  const std::vector<Pose2> corner = unsmoothedCorner();
  for (const std::string& controller : {"setpoint", "los"}) {
    PlannerParameters parameters = withVehicle("kinematic");
    parameters.controller = controller;
    const RobotModel model = robotModelOf(parameters);
    TrajectoryFollower follower(model, corner, restingAt(corner.front()),
                                PoseSequenceTiming(model.vehicle).times(corner));
    const double slack = parameters.a_max * parameters.sim_dt;
    int checked = 0;
    while (!follower.finished() && follower.state().pose.x < 5.0 - 1e-9 &&
           follower.state().t < 100.0) {
      const double d = std::max(0.0, 5.0 - follower.state().pose.x);
      follower.step();
      EXPECT_LE(
          follower.state().speed,
          std::sqrt(2.0 * parameters.a_max * (d + parameters.v_max * parameters.sim_dt)) + slack)
          << controller << " at t = " << follower.state().t;
      ++checked;
    }
    EXPECT_GT(checked, 10) << controller;
  }
}

/// The default parameters with `controller` on `vehicle_model`.
PlannerParameters withController(const std::string& controller, const std::string& vehicle_model) {
  PlannerParameters parameters = withVehicle(vehicle_model);
  parameters.controller = controller;
  return parameters;
}

/// `poses` timed at a constant `speed` between distinct positions, 1 s per in-place step.
std::vector<double> timesAt(const std::vector<Pose2>& poses, double speed) {
  std::vector<double> times{0.0};
  for (std::size_t i = 1; i < poses.size(); ++i) {
    const double length = (poses[i].position() - poses[i - 1].position()).norm();
    times.push_back(times.back() + (length > 0.0 ? length / speed : 1.0));
  }
  return times;
}

TEST(TrajectoryFollowerTest, ThePoseStreamReleasesPoseIAtIOverTheRate) {
  // pose_stream tracks the reference that passes pose i at i / pose_rate, whatever the
  // trajectory's own times, and so cannot finish before the last pose is released.
  PlannerParameters parameters = withController("pose_stream", "dynamic");
  parameters.pose_rate = 2.0;
  const std::vector<Pose2> poses = unsmoothedCorner();
  TrajectoryFollower follower(robotModelOf(parameters), poses, restingAt(poses.front()),
                              timesAt(poses, 0.1));
  const TimedReference* reference = follower.reference();
  ASSERT_NE(reference, nullptr);
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const ReferenceState at = reference->at(static_cast<double>(i) / parameters.pose_rate);
    EXPECT_NEAR((at.position - poses[i].position()).norm(), 0.0, 1e-12) << i;
    EXPECT_NEAR(wrapAngle(at.yaw - poses[i].yaw), 0.0, 1e-12) << i;
  }
  const double last_release = static_cast<double>(poses.size() - 1) / parameters.pose_rate;
  EXPECT_DOUBLE_EQ(reference->endTime(), last_release);
  while (!follower.finished() && follower.state().t < 200.0) follower.step();
  ASSERT_TRUE(follower.finished());
  EXPECT_GE(follower.state().t, last_release);
  // It needs no times of its own.
  EXPECT_NO_THROW(TrajectoryFollower(robotModelOf(parameters), poses, restingAt(poses.front())));
}

TEST(TrajectoryFollowerTest, LineOfSightCommandsTheCourseOfItsLaw) {
  // A kinematic robot at rest 0.05 m to the left of a line along +x, heading along it: its
  // first yaw-rate command is yaw_gain times the law's course -atan(y_e / Delta) (no
  // sideslip at rest), here within yaw_rate_max; Delta is the turning radius by default.
  const PlannerParameters parameters = withController("los", "kinematic");
  const RobotModel model = robotModelOf(parameters);
  const std::vector<Pose2> poses = straightLine(20.0, 20.0);
  const double offset = 0.05;
  TrajectoryFollower follower(model, poses, restingAt({0.0, offset, 0.0}), timesAt(poses, 0.4));
  follower.step();
  const double course = -std::atan(offset / parameters.turning_radius);
  ASSERT_LT(std::abs(parameters.yaw_gain * course), parameters.yaw_rate_max);
  EXPECT_NEAR(follower.state().yaw_rate, parameters.yaw_gain * course, 1e-12);
  EXPECT_NEAR(course,
              LineOfSightGuidance(parameters.turning_radius)
                  .course(poses[0].position(), poses[1].position(), {0.0, offset}),
              1e-15);
}

TEST(TrajectoryFollowerTest, LineOfSightClosesTheCrossTrackErrorMonotonically) {
  // 1 m off a straight line, heading along it: the cross-track error decays without
  // overshoot on both vehicles and with look-aheads of 0.5, 1 and 2 turning radii.
  const std::vector<Pose2> poses = straightLine(40.0, 1.0);
  for (const std::string& vehicle : kVehicles) {
    for (const double lookahead : {0.5, 1.0, 2.0}) {
      PlannerParameters parameters = withController("los", vehicle);
      parameters.los_lookahead = lookahead * parameters.turning_radius;
      TrajectoryFollower follower(robotModelOf(parameters), poses, restingAt({0.0, 1.0, 0.0}),
                                  timesAt(poses, 0.4));
      double previous = 1.0;
      while (!follower.finished() && follower.state().pose.x < 30.0 && follower.state().t < 200.0) {
        follower.step();
        const double error = std::abs(follower.state().pose.y);
        EXPECT_LE(error, previous + 1e-12)
            << vehicle << " " << lookahead << " at t = " << follower.state().t;
        previous = error;
      }
      EXPECT_LT(previous, 0.01) << vehicle << " " << lookahead;
    }
  }
}

TEST(TrajectoryFollowerTest, LineOfSightHoldsItsLineInACrossCurrent) {
  // Steering the heading off the course by the measured sideslip, the robot crabs along
  // the line in a cross current instead of settling beside it.
  for (const std::string& vehicle : kVehicles) {
    PlannerParameters parameters = withController("los", vehicle);
    parameters.current_y = 0.1;
    const std::vector<Pose2> poses = straightLine(40.0, 1.0);
    TrajectoryFollower follower(robotModelOf(parameters), poses, restingAt(poses.front()),
                                timesAt(poses, 0.4));
    while (!follower.finished() && follower.state().pose.x < 30.0 && follower.state().t < 300.0) {
      follower.step();
    }
    EXPECT_NEAR(follower.state().pose.x, 30.0, 0.1) << vehicle;
    EXPECT_LT(std::abs(follower.state().pose.y), 0.02) << vehicle;
  }
}

TEST(TrajectoryFollowerTest, LineOfSightTurnsInPlaceAndArrives) {
  const std::vector<Pose2> poses = unsmoothedCorner();
  for (const std::string& vehicle : kVehicles) {
    const PlannerParameters parameters = withController("los", vehicle);
    const SimulationResult result =
        RobotSimulator(robotModelOf(parameters)).simulate(poses, timesAt(poses, 0.4));
    const Pose2& end = result.steps.back().pose;
    EXPECT_LT((end.position() - poses.back().position()).norm(),
              2.0 * parameters.position_tolerance)
        << vehicle;
    EXPECT_LT(result.tracking.percentiles_m.back(), 0.1) << vehicle;
  }
}

TEST(TrajectoryFollowerTest, LineOfSightNeedsTheTrajectorysTimes) {
  const RobotModel model = robotModelOf(withController("los", "kinematic"));
  EXPECT_THROW(TrajectoryFollower(model, {{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}}, RobotState{}),
               InvalidInputError);
  EXPECT_THROW(
      TrajectoryFollower(model, {{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}}, RobotState{}, {1.0, 0.0}),
      InvalidInputError);
}

}  // namespace
}  // namespace kinematic_coverage::core
