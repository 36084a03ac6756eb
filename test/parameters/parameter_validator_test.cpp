#include "polygon_coverage_ros_bridge/parameters/parameter_validator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {
namespace {

std::string errorOf(const std::function<void(PlannerParameters&)>& change) {
  PlannerParameters parameters;
  change(parameters);
  try {
    ParameterValidator().validate(parameters);
  } catch (const InvalidInputError& error) {
    return error.what();
  }
  return "";
}

TEST(ParameterValidator, AcceptsTheDefaultsAndTheBoundaries) {
  EXPECT_EQ(errorOf([](PlannerParameters&) {}), "");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.wall_distance = 0.0; }), "");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.lateral_overlap = 0.0; }), "");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.lateral_overlap = 0.99; }), "");
  EXPECT_EQ(errorOf([](PlannerParameters& p) {
              p.decomposition_type = "trapezoidal";
              p.cost_function = "waypoints";
              p.sensor_model = "line";
              p.replanning_method = "concave_hull";
            }),
            "");
}

TEST(ParameterValidator, RejectsNonPositiveLengthsSpeedsAndSampling) {
  const std::vector<std::pair<std::string, double PlannerParameters::*>> positive = {
      {"turning_radius", &PlannerParameters::turning_radius},
      {"sensor_distance", &PlannerParameters::sensor_distance},
      {"v_max", &PlannerParameters::v_max},
      {"a_max", &PlannerParameters::a_max},
      {"yaw_rate_max", &PlannerParameters::yaw_rate_max},
      {"segment_sampling_distance", &PlannerParameters::segment_sampling_distance},
      {"arc_sampling_distance", &PlannerParameters::arc_sampling_distance},
      {"rotation_sampling_angle", &PlannerParameters::rotation_sampling_angle},
      {"lateral_footprint", &PlannerParameters::lateral_footprint},
      {"alpha", &PlannerParameters::alpha},
  };
  for (const auto& [name, member] : positive) {
    for (const double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(),
                             std::numeric_limits<double>::infinity()}) {
      const std::string message =
          errorOf([&, field = member](PlannerParameters& p) { p.*field = bad; });
      EXPECT_EQ(message.rfind(name + " = ", 0), 0u) << message;
      EXPECT_NE(message.find("is out of range: it must be a finite number > 0"), std::string::npos)
          << message;
    }
  }
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.turning_radius = -2.5; }),
            "turning_radius = -2.5 is out of range: it must be a finite number > 0 (m)");
}

TEST(ParameterValidator, RejectsANegativeWallDistance) {
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.wall_distance = -0.1; }),
            "wall_distance = -0.1 is out of range: it must be a finite number >= 0 (m)");
}

TEST(ParameterValidator, ChecksTheTurningRadii) {
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.max_turning_radius = 1.0; }), "");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.max_turning_radius = 2.5; }), "");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.max_turning_radius = 0.5; }),
            "max_turning_radius = 0.5 is out of range: it must be at least turning_radius = 1, "
            "or 0 for max(turning_radius, v_max / yaw_rate_max) (m)");
  for (const double bad :
       {-1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    const std::string message =
        errorOf([bad](PlannerParameters& p) { p.max_turning_radius = bad; });
    EXPECT_EQ(message.rfind("max_turning_radius = ", 0), 0u) << message;
  }
  EXPECT_EQ(errorOf([](PlannerParameters& p) {
              p.min_turning_radius = 1.5;
            }).rfind("min_turning_radius = 1.5 is out of range", 0),
            0u);
}

TEST(ParameterValidator, RejectsOverlapOutsideZeroToOne) {
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.lateral_overlap = 1.0; }),
            "lateral_overlap = 1 is out of range: it must be in [0, 1)");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.lateral_overlap = -0.2; }),
            "lateral_overlap = -0.2 is out of range: it must be in [0, 1)");
}

TEST(ParameterValidator, ChecksTheBoundarySimplificationShare) {
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.boundary_simplification = 0.5; }), "");
  const std::string expected =
      " is out of range: it must be in [0, 0.5] (a share of the sweep distance)";
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.boundary_simplification = 0.6; }),
            "boundary_simplification = 0.6" + expected);
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.boundary_simplification = -0.01; }),
            "boundary_simplification = -0.01" + expected);
  EXPECT_EQ(errorOf([](PlannerParameters& p) {
              p.boundary_simplification = std::numeric_limits<double>::quiet_NaN();
            }),
            "boundary_simplification = nan" + expected);
}

TEST(ParameterValidator, RejectsFieldsOfViewOutsideZeroToPi) {
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.lateral_fov = M_PI; }),
            "lateral_fov = 3.141592654 is out of range: it must be in (0, pi) rad");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.onward_fov = 0.0; }),
            "onward_fov = 0 is out of range: it must be in (0, pi) rad");
}

TEST(ParameterValidator, RejectsUnknownNames) {
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.decomposition_type = "voronoi"; }),
            "decomposition_type = 'voronoi' is not one of: boustrophedon, trapezoidal");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.cost_function = "Time"; }),
            "cost_function = 'Time' is not one of: distance, time, waypoints");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.sensor_model = ""; }),
            "sensor_model = '' is not one of: frustum, line");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.replanning_method = "alpha"; }),
            "replanning_method = 'alpha' is not one of: convex_hull, concave_hull, footprint");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.coverage_safe_area = "all"; }),
            "coverage_safe_area = 'all' is not one of: free, reachable");
}

TEST(ParameterValidator, ChecksTheRobotModelsRanges) {
  for (const auto& [name, member] :
       std::vector<std::pair<std::string, double PlannerParameters::*>>{
           {"yaw_gain", &PlannerParameters::yaw_gain},
           {"position_gain", &PlannerParameters::position_gain},
           {"position_tolerance", &PlannerParameters::position_tolerance},
           {"sim_dt", &PlannerParameters::sim_dt},
           {"sim_time_limit", &PlannerParameters::sim_time_limit},
           {"mass", &PlannerParameters::mass},
           {"inertia_yaw", &PlannerParameters::inertia_yaw},
           {"thrust_max", &PlannerParameters::thrust_max},
           {"yaw_torque_max", &PlannerParameters::yaw_torque_max},
           {"surge_loop_gain", &PlannerParameters::surge_loop_gain},
           {"yaw_rate_loop_gain", &PlannerParameters::yaw_rate_loop_gain}}) {
    const std::string message = errorOf([field = member](PlannerParameters& p) { p.*field = 0.0; });
    EXPECT_EQ(message.rfind(name + " = 0 is out of range: it must be a finite number > 0", 0), 0u)
        << message;
  }
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.yaw_tolerance = M_PI; }),
            "yaw_tolerance = 3.141592654 is out of range: it must be in (0, pi) rad");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.current_y = std::nan(""); }),
            "current_y = nan is out of range: it must be a finite number (m/s)");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.current_x = -3.0; }), "");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.smoothing_clearance = -0.5; }),
            "smoothing_clearance = -0.5 is out of range: it must be a finite number >= 0 (m), or "
            "wall_distance");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.smoothing_clearance = kClearanceOfWallDistance; }),
            "");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.smoothing_clearance = 0.5; }), "");
  // gap_clearance in (0, wall_distance], ignored when wall_distance is 0.
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.gap_clearance = 1.5; }),
            "gap_clearance = 1.5 is out of range: it must be in (0, wall_distance = 1] (m), or "
            "wall_distance");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.gap_clearance = 0.0; }),
            "gap_clearance = 0 is out of range: it must be in (0, wall_distance = 1] (m), or "
            "wall_distance");
  EXPECT_NE(errorOf([](PlannerParameters& p) { p.gap_clearance = std::nan(""); }), "");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.gap_clearance = 1.0; }), "");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.gap_clearance = 0.01; }), "");
  EXPECT_EQ(errorOf([](PlannerParameters& p) {
              p.wall_distance = 0.0;
              p.gap_clearance = 3.0;
            }),
            "");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.current_sigma = -0.01; }),
            "current_sigma = -0.01 is out of range: it must be a finite number >= 0 (m/s)");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.navigation_sigma = INFINITY; }),
            "navigation_sigma = inf is out of range: it must be a finite number >= 0 (m)");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.current_time_constant = 0.0; }),
            "current_time_constant = 0 is out of range: it must be a finite number > 0 (s)");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.navigation_time_constant = -1.0; }),
            "navigation_time_constant = -1 is out of range: it must be a finite number > 0 (s)");
  for (const double seed : {-1.0, 1.5, 4294967296.0, std::nan("")}) {
    const std::string message =
        errorOf([seed](PlannerParameters& p) { p.disturbance_seed = seed; });
    EXPECT_NE(message.find("disturbance_seed = "), std::string::npos) << seed;
    EXPECT_NE(message.find("it must be an integer in [0, 4294967295]"), std::string::npos)
        << message;
  }
  EXPECT_EQ(errorOf([](PlannerParameters& p) {
              p.current_sigma = 0.0;
              p.navigation_sigma = 0.0;
              p.disturbance_seed = 0.0;
            }),
            "");
  EXPECT_EQ(errorOf([](PlannerParameters& p) {
              p.yaw_gain = 4.0;
              p.sim_dt = 0.5;
            }),
            "yaw_gain = 4 with sim_dt = 0.5 is out of range: yaw_gain * sim_dt must be <= 1");
  EXPECT_EQ(errorOf([](PlannerParameters& p) {
              p.yaw_gain = 10.0;
              p.sim_dt = 0.1;
            }),
            "");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.yaw_rate_loop_gain = 11.0; }),
            "yaw_rate_loop_gain = 11 with sim_dt = 0.1 is out of range: yaw_rate_loop_gain * "
            "sim_dt must be <= 1");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.surge_loop_gain = 20.0; }),
            "surge_loop_gain = 20 with sim_dt = 0.1 is out of range: surge_loop_gain * sim_dt "
            "must be <= 1");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.turn_curve = "spline"; }),
            "turn_curve = 'spline' is not one of: arc, clothoid");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.curvature_rate_max = 0.0; }),
            "curvature_rate_max = 0 is out of range: it must be a finite number > 0 (1/m^2)");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.vehicle_model = "holonomic"; }),
            "vehicle_model = 'holonomic' is not one of: dynamic, kinematic");
  // Added masses and damping may be 0 (an idealised body), not negative.
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.added_mass_sway = 0.0; }), "");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.damping_sway_quadratic = -1.0; }),
            "damping_sway_quadratic = -1 is out of range: it must be a finite number >= 0 "
            "(N s^2/m^2)");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.damping_yaw_linear = std::nan(""); }),
            "damping_yaw_linear = nan is out of range: it must be a finite number >= 0 "
            "(N m s/rad)");
}

}  // namespace
}  // namespace kinematic_coverage::core
