#include "coverage_system/parameters/stage_options.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "coverage_system/parameters/parameter_choices.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {
namespace {

/// Every composer of a stage's whole options, so that each can be asked to reject the same
/// parameter set.
std::vector<std::function<void(const PlannerParameters&)>> everyMapping() {
  return {[](const PlannerParameters& p) { planningOptionsOf(p); },
          [](const PlannerParameters& p) { globalSmoothingOptionsOf(p); },
          [](const PlannerParameters& p) { trajectoryOptionsOf(p); },
          [](const PlannerParameters& p) { robotModelOf(p); },
          [](const PlannerParameters& p) { remainingAreaOptionsOf(p); }};
}

TEST(StageOptions, TheDefaultsMapToTheDocumentedStageOptions) {
  const PlannerParameters p;
  const VehicleLimits vehicle = vehicleLimitsOf(p);
  EXPECT_EQ(vehicle.v_max, p.v_max);
  EXPECT_EQ(vehicle.a_max, p.a_max);
  EXPECT_EQ(vehicle.yaw_rate_max, p.yaw_rate_max);
  EXPECT_EQ(vehicle.turning_radius, p.turning_radius);
  EXPECT_EQ(planningOptionsOf(p).decomposition_type, DecompositionType::kBoustrophedon);
  EXPECT_EQ(planningOptionsOf(p).offset_parts, OffsetParts::kAll);
  EXPECT_EQ(sensorOptionsOf(p).model, SensorModel::kFrustum);
  // The frustum's footprint: W = 2 d tan(lateral_fov / 2), L = 2 d tan(onward_fov / 2).
  const FrustumSensor sensor = sensorOf(p);
  EXPECT_DOUBLE_EQ(sensor.width(), 2.0 * p.sensor_distance * std::tan(0.5 * p.lateral_fov));
  EXPECT_DOUBLE_EQ(sensor.length(), 2.0 * p.sensor_distance * std::tan(0.5 * p.onward_fov));
  EXPECT_DOUBLE_EQ(sensor.sweepDistance(), (1.0 - p.lateral_overlap) * sensor.width());
  // cost_function time: rest to rest, L / v + v / a on a segment long enough to cruise.
  EXPECT_DOUBLE_EQ(segmentCostOf(p).ofLength(10.0), 10.0 / p.v_max + p.v_max / p.a_max);

  const TrajectoryOptions trajectory = trajectoryOptionsOf(p);
  EXPECT_TRUE(trajectory.smoothing);
  EXPECT_EQ(trajectory.strategy, SmoothingStrategy::kCoverageSafe);
  EXPECT_EQ(trajectory.segment_sampling_distance, p.segment_sampling_distance);
  EXPECT_EQ(trajectory.arc_sampling_distance, p.arc_sampling_distance);
  EXPECT_EQ(trajectory.rotation_sampling_angle, p.rotation_sampling_angle);
  EXPECT_EQ(trajectory.turn_curve, TurnCurve::kArc);
  EXPECT_EQ(trajectory.curvature_rate_max, p.curvature_rate_max);
  // One robot for every strategy and for the timing.
  EXPECT_EQ(&trajectory.vehicle(), &trajectory.global.vehicle);
  EXPECT_EQ(trajectory.vehicle().turning_radius, p.turning_radius);
  EXPECT_EQ(trajectory.vehicle().yaw_rate_max, p.yaw_rate_max);
  // Coverage-safe: the safe sensor, bulb turns, and the radius of an arc at v_max.
  EXPECT_TRUE(trajectory.global.safe_sensor.has_value());
  EXPECT_FALSE(trajectory.global.preserved_sensor.has_value());
  EXPECT_TRUE(trajectory.global.bulb_turns);
  EXPECT_EQ(trajectory.global.wall_distance, p.wall_distance);
  EXPECT_EQ(trajectory.global.min_turning_radius, p.turning_radius);
  EXPECT_EQ(trajectory.global.max_turning_radius,
            std::max(p.turning_radius, p.v_max / p.yaw_rate_max));

  EXPECT_EQ(trajectory.global.clearance, p.wall_distance);
  EXPECT_EQ(trajectory.wall_distance, p.wall_distance);
  PlannerParameters kept = p;
  kept.smoothing_clearance = 0.4;
  EXPECT_EQ(trajectoryOptionsOf(kept).global.clearance, 0.4);

  const RobotModel robot = robotModelOf(p);
  EXPECT_EQ(robot.vehicle_model, VehicleModel::kDynamic);
  EXPECT_EQ(robot.body.mass, p.mass);
  EXPECT_EQ(robot.body.added_mass_surge, p.added_mass_surge);
  EXPECT_EQ(robot.body.added_mass_sway, p.added_mass_sway);
  EXPECT_EQ(robot.body.inertia_yaw, p.inertia_yaw);
  EXPECT_EQ(robot.body.added_inertia_yaw, p.added_inertia_yaw);
  EXPECT_EQ(robot.body.damping_surge_linear, p.damping_surge_linear);
  EXPECT_EQ(robot.body.damping_sway_linear, p.damping_sway_linear);
  EXPECT_EQ(robot.body.damping_yaw_linear, p.damping_yaw_linear);
  EXPECT_EQ(robot.body.damping_surge_quadratic, p.damping_surge_quadratic);
  EXPECT_EQ(robot.body.damping_sway_quadratic, p.damping_sway_quadratic);
  EXPECT_EQ(robot.body.damping_yaw_quadratic, p.damping_yaw_quadratic);
  EXPECT_EQ(robot.body.thrust_max, p.thrust_max);
  EXPECT_EQ(robot.body.yaw_torque_max, p.yaw_torque_max);
  EXPECT_EQ(robot.surge_loop_gain, p.surge_loop_gain);
  EXPECT_EQ(robot.yaw_rate_loop_gain, p.yaw_rate_loop_gain);
  EXPECT_EQ(robot.vehicle.v_max, p.v_max);
  EXPECT_EQ(robot.yaw_gain, p.yaw_gain);
  EXPECT_EQ(robot.position_gain, p.position_gain);
  EXPECT_EQ(robot.position_tolerance, p.position_tolerance);
  EXPECT_EQ(robot.yaw_tolerance, p.yaw_tolerance);
  EXPECT_EQ(robot.sim_dt, p.sim_dt);
  EXPECT_EQ(robot.sim_time_limit, p.sim_time_limit);
  EXPECT_EQ(robot.disturbance.current_sigma, 0.0);
  EXPECT_EQ(robot.disturbance.navigation_sigma, 0.0);
  EXPECT_EQ(robot.disturbance.current_time_constant, p.current_time_constant);
  EXPECT_EQ(robot.disturbance.navigation_time_constant, p.navigation_time_constant);
  EXPECT_EQ(robot.disturbance.seed, 1u);
  PlannerParameters lake = p;
  lake.current_sigma = 0.02;
  lake.navigation_sigma = 0.1;
  lake.disturbance_seed = 4294967295.0;
  const RobotModel lake_robot = robotModelOf(lake);
  EXPECT_EQ(lake_robot.disturbance.current_sigma, 0.02);
  EXPECT_EQ(lake_robot.disturbance.navigation_sigma, 0.1);
  EXPECT_EQ(lake_robot.disturbance.seed, 4294967295u);

  const RemainingAreaOptions remaining = remainingAreaOptionsOf(p);
  EXPECT_EQ(remaining.method, ReplanningMethod::kFootprint);
  EXPECT_EQ(remaining.sliver_fraction, p.replanning_sliver_fraction);
  EXPECT_EQ(remaining.min_area, p.replanning_min_area);
  EXPECT_EQ(remaining.simplify_tolerance, p.replanning_simplify_tolerance);
  EXPECT_EQ(remaining.alpha, p.alpha);
}

TEST(StageOptions, ThePlanningOptionsResolveTheWordsAndShares) {
  PlannerParameters p;
  p.wall_distance = 1.5;
  const PlanningOptions planning = planningOptionsOf(p);
  EXPECT_EQ(planning.wall_distance, 1.5);
  EXPECT_EQ(planning.gap_clearance, 1.5);  // the word wall_distance
  EXPECT_DOUBLE_EQ(planning.boundary_simplification,
                   p.boundary_simplification * sensorOf(p).sweepDistance());
  EXPECT_EQ(planning.cost_function, CostFunction::kTime);
  EXPECT_EQ(planning.vehicle.turning_radius, p.turning_radius);
  EXPECT_TRUE(planning.coverage_repair);
  p.gap_clearance = 0.5;
  EXPECT_EQ(planningOptionsOf(p).gap_clearance, 0.5);
}

TEST(StageOptions, EveryNameMapsToItsOwnOption) {
  PlannerParameters p;
  for (const auto& [name, type] : kDecompositionTypes) {
    p.decomposition_type = name;
    EXPECT_EQ(planningOptionsOf(p).decomposition_type, type) << name;
  }
  for (const auto& [name, joining] : kCellJoinings) {
    p.cell_joining = name;
    EXPECT_EQ(planningOptionsOf(p).cell_joining, joining) << name;
  }
  for (const auto& [name, parts] : kOffsetParts) {
    p.offset_parts = name;
    EXPECT_EQ(planningOptionsOf(p).offset_parts, parts) << name;
  }
  for (const auto& [name, model] : kSensorModels) {
    p.sensor_model = name;
    EXPECT_EQ(sensorOptionsOf(p).model, model) << name;
  }
  for (const auto& [name, strategy] : kSmoothingStrategies) {
    p.smoothing_strategy = name;
    EXPECT_EQ(trajectoryOptionsOf(p).strategy, strategy) << name;
  }
  for (const auto& [name, method] : kReplanningMethods) {
    p.replanning_method = name;
    EXPECT_EQ(remainingAreaOptionsOf(p).method, method) << name;
  }
  // The three cost functions differ on a 10 m segment: 10 m, 22.5 s, one segment.
  p = PlannerParameters();
  std::vector<double> costs;
  for (const auto& [name, function] : kCostFunctions) {
    p.cost_function = name;
    costs.push_back(segmentCostOf(p).ofLength(10.0));
  }
  EXPECT_EQ(costs, (std::vector<double>{10.0, 10.0 / p.v_max + p.v_max / p.a_max, 1.0}));
}

TEST(StageOptions, TheLineSensorAndTheOtherStrategiesMapAsDocumented) {
  PlannerParameters p;
  p.sensor_model = "line";
  p.lateral_footprint = 3.0;
  EXPECT_EQ(sensorOf(p).width(), 3.0);
  EXPECT_EQ(sensorOf(p).length(), 0.0);

  p = PlannerParameters();
  p.smoothing_strategy = "global";
  p.min_turning_radius = 0.5;
  p.coverage_preserving = true;
  const GlobalSmoothingOptions global = globalSmoothingOptionsOf(p);
  EXPECT_EQ(global.min_turning_radius, 0.5);
  EXPECT_TRUE(global.preserved_sensor.has_value());
  EXPECT_FALSE(global.safe_sensor.has_value());
  EXPECT_FALSE(global.bulb_turns);

  p = PlannerParameters();
  p.max_turning_radius = 3.0;
  EXPECT_EQ(globalSmoothingOptionsOf(p).max_turning_radius, 3.0);
}

TEST(StageOptions, EveryMappingRejectsAParameterSetOutOfRange) {
  std::vector<std::function<void(PlannerParameters&)>> changes = {
      [](PlannerParameters& p) { p.v_max = -1.0; },
      [](PlannerParameters& p) { p.lateral_overlap = 1.0; },
      [](PlannerParameters& p) { p.sensor_model = "sonar"; },
      [](PlannerParameters& p) { p.cell_joining = "anywhere"; },
      [](PlannerParameters& p) { p.replanning_method = "guess"; },
      [](PlannerParameters& p) { p.sim_dt = std::nan(""); }};
  for (std::size_t change = 0; change < changes.size(); ++change) {
    PlannerParameters p;
    changes[change](p);
    for (std::size_t mapping = 0; mapping < everyMapping().size(); ++mapping) {
      EXPECT_THROW(everyMapping()[mapping](p), InvalidInputError)
          << "change " << change << ", mapping " << mapping;
    }
  }
}

TEST(StageOptions, AnUnknownNameIsRejectedWithTheNamesAllowed) {
  PlannerParameters p;
  p.smoothing_strategy = "spline";
  try {
    trajectoryOptionsOf(p);
    FAIL() << "no error";
  } catch (const InvalidInputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "smoothing_strategy = 'spline' is not one of: coverage_safe, global, local");
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
