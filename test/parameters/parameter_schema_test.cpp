#include "coverage_system/parameters/parameter_schema.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {
namespace {

std::string errorOf(const std::function<void(PlannerParameters&)>& change) {
  PlannerParameters parameters;
  change(parameters);
  try {
    checkParameters(parameters);
  } catch (const InvalidInputError& error) {
    return error.what();
  }
  return "";
}

TEST(ParameterSchema, AcceptsTheDefaultsAndTheBoundaries) {
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

TEST(ParameterSchema, RejectsNonPositiveLengthsSpeedsAndSampling) {
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

TEST(ParameterSchema, RejectsANegativeWallDistance) {
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.wall_distance = -0.1; }),
            "wall_distance = -0.1 is out of range: it must be a finite number >= 0 (m)");
}

TEST(ParameterSchema, ChecksTheTurningRadii) {
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.max_turning_radius = 1.0; }), "");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.max_turning_radius = 2.5; }), "");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.max_turning_radius = 0.5; }),
            "max_turning_radius = 0.5 is out of range: it must be 0 or >= turning_radius = 1 "
            "(m)");
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

TEST(ParameterSchema, RejectsOverlapOutsideZeroToOne) {
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.lateral_overlap = 1.0; }),
            "lateral_overlap = 1 is out of range: it must be in [0, 1)");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.lateral_overlap = -0.2; }),
            "lateral_overlap = -0.2 is out of range: it must be in [0, 1)");
}

TEST(ParameterSchema, ChecksTheBoundarySimplificationShare) {
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.boundary_simplification = 0.5; }), "");
  const std::string expected = " is out of range: it must be in [0, 0.5]";
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.boundary_simplification = 0.6; }),
            "boundary_simplification = 0.6" + expected);
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.boundary_simplification = -0.01; }),
            "boundary_simplification = -0.01" + expected);
  EXPECT_EQ(errorOf([](PlannerParameters& p) {
              p.boundary_simplification = std::numeric_limits<double>::quiet_NaN();
            }),
            "boundary_simplification = nan" + expected);
}

TEST(ParameterSchema, RejectsFieldsOfViewOutsideZeroToPi) {
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.lateral_fov = M_PI; }),
            "lateral_fov = 3.141592654 is out of range: it must be in (0, pi) (rad)");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.onward_fov = 0.0; }),
            "onward_fov = 0 is out of range: it must be in (0, pi) (rad)");
}

TEST(ParameterSchema, RejectsUnknownNames) {
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

TEST(ParameterSchema, ChecksTheRobotModelsRanges) {
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
           {"yaw_rate_loop_gain", &PlannerParameters::yaw_rate_loop_gain},
           {"tracking_natural_frequency", &PlannerParameters::tracking_natural_frequency},
           {"tracking_damping", &PlannerParameters::tracking_damping},
           {"pose_rate", &PlannerParameters::pose_rate}}) {
    const std::string message = errorOf([field = member](PlannerParameters& p) { p.*field = 0.0; });
    EXPECT_EQ(message.rfind(name + " = 0 is out of range: it must be a finite number > 0", 0), 0u)
        << message;
  }
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.los_lookahead = -1.0; }),
            "los_lookahead = -1 is out of range: it must be a finite number >= 0 (m)");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.tracking_natural_frequency = 6.0; }),
            "tracking_natural_frequency = 6 is out of range: it must be a finite number > 0 "
            "(rad/s), and tracking_natural_frequency * sim_dt <= 0.5 (sim_dt = 0.1)");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.controller = "pid"; }),
            "controller = 'pid' is not one of: los, pose_stream, setpoint, timed");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.yaw_tolerance = M_PI; }),
            "yaw_tolerance = 3.141592654 is out of range: it must be in (0, pi) (rad)");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.current_y = std::nan(""); }),
            "current_y = nan is out of range: it must be a finite number (m/s)");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.current_x = -3.0; }), "");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.smoothing_clearance = -0.5; }),
            "smoothing_clearance = -0.5 is out of range: it must be a finite number >= 0 (m), or "
            "the word wall_distance");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.smoothing_clearance = kClearanceOfWallDistance; }),
            "");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.smoothing_clearance = 0.5; }), "");
  // gap_clearance in (0, wall_distance], ignored when wall_distance is 0.
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.gap_clearance = 1.5; }),
            "gap_clearance = 1.5 is out of range: it must be in (0, wall_distance = 1] (m), or the "
            "word wall_distance; ignored when wall_distance is 0");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.gap_clearance = 0.0; }),
            "gap_clearance = 0 is out of range: it must be in (0, wall_distance = 1] (m), or the "
            "word wall_distance; ignored when wall_distance is 0");
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
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.yaw_gain = 12.0; }),
            "yaw_gain = 12 is out of range: it must be a finite number > 0 (1/s), and yaw_gain * "
            "sim_dt <= 1 (sim_dt = 0.1)");
  EXPECT_EQ(errorOf([](PlannerParameters& p) {
              p.yaw_gain = 10.0;
              p.sim_dt = 0.1;
            }),
            "");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.yaw_rate_loop_gain = 11.0; }),
            "yaw_rate_loop_gain = 11 is out of range: it must be a finite number > 0 (1/s), and "
            "yaw_rate_loop_gain * sim_dt <= 1 (sim_dt = 0.1)");
  EXPECT_EQ(errorOf([](PlannerParameters& p) { p.surge_loop_gain = 20.0; }),
            "surge_loop_gain = 20 is out of range: it must be a finite number > 0 (1/s), and "
            "surge_loop_gain * sim_dt <= 1 (sim_dt = 0.1)");
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

std::string fileText(const std::string& relative_path) {
  std::ifstream in(std::string(KC_SOURCE_DIR) + "/" + relative_path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string trimmed(const std::string& text) {
  const std::size_t first = text.find_first_not_of(' ');
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(' ') - first + 1);
}

/// The cells of the markdown table rows of `section` (from its heading to the next heading
/// of the same level) whose first cell starts with a backtick.
std::vector<std::vector<std::string>> tableRows(const std::string& document,
                                                const std::string& section) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(document);
  std::string line;
  bool inside = false;
  while (std::getline(lines, line)) {
    if (line.rfind("## ", 0) == 0) inside = line == section;
    if (!inside || line.rfind("| `", 0) != 0) continue;
    std::vector<std::string> cells;
    std::istringstream row(line.substr(1));
    std::string cell;
    while (std::getline(row, cell, '|')) cells.push_back(trimmed(cell));
    rows.push_back(cells);
  }
  return rows;
}

std::string withoutBackticks(std::string text) {
  text.erase(std::remove(text.begin(), text.end(), '`'), text.end());
  return text;
}

/// Whether a table's default cell says the declared default (numbers compared as numbers).
bool sameDefault(const ParameterDeclaration& declaration, const std::string& cell) {
  const std::string text = withoutBackticks(cell);
  const std::string declared = parameterValueText(declaration, declaration.default_value);
  if (text == declared) return true;
  char* end = nullptr;
  const double number = std::strtod(text.c_str(), &end);
  return end != text.c_str() && *end == '\0' &&
         std::holds_alternative<double>(declaration.default_value) &&
         number == std::get<double>(declaration.default_value);
}

TEST(ParameterSchema, EveryDeclarationIsComplete) {
  const std::vector<ParameterDeclaration>& schema = parameterSchema();
  for (std::size_t i = 0; i < schema.size(); ++i) {
    const ParameterDeclaration& d = schema[i];
    SCOPED_TRACE(d.name);
    EXPECT_EQ(findParameter(d.name), &d);
    for (std::size_t j = 0; j < i; ++j) EXPECT_FALSE(schema[j].member == d.member);
    EXPECT_EQ(d.member.index(), d.default_value.index());
    ASSERT_GT(std::string(d.description).size(), 10u);
    EXPECT_EQ(std::string(d.description).back(), '.');
    const bool is_name = std::holds_alternative<std::string PlannerParameters::*>(d.member);
    EXPECT_EQ(is_name, !d.choices.empty());
    if (is_name) {
      EXPECT_NE(
          std::find(d.choices.begin(), d.choices.end(), std::get<std::string>(d.default_value)),
          d.choices.end());
    }
    EXPECT_TRUE(d.word == nullptr || std::holds_alternative<double PlannerParameters::*>(d.member));
  }
  EXPECT_EQ(errorOf([](PlannerParameters&) {}), "");
}

TEST(ParameterSchema, AssigningChecksTheTypeAndTheRangeAndNamesTheOrigin) {
  const auto assignError = [](const char* name, const ParameterValue& value) {
    PlannerParameters p;
    try {
      assignParameter(p, *findParameter(name), value, "here:3");
    } catch (const InvalidInputError& error) {
      return std::string(error.what());
    }
    return std::string();
  };
  EXPECT_EQ(assignError("lateral_overlap", 1.0),
            "here:3: lateral_overlap = 1 is out of range: it must be in [0, 1)");
  EXPECT_EQ(assignError("v_max", std::string("fast")),
            "here:3: v_max: the value 'fast' is not a number");
  EXPECT_EQ(assignError("smoothing", 1.0), "here:3: smoothing: the value 1 is not true or false");
  EXPECT_EQ(assignError("turn_curve", true), "here:3: turn_curve: the value true is not a name");
  EXPECT_EQ(assignError("turn_curve", std::string("spline")),
            "here:3: turn_curve = 'spline' is not one of: arc, clothoid");
  // A clearance's stand-in for the wall distance is only ever the word.
  EXPECT_NE(assignError("gap_clearance", kClearanceOfWallDistance), "");
  EXPECT_EQ(assignError("gap_clearance", std::string("wall_distance")), "");
  PlannerParameters p;
  assignParameter(p, *findParameter("smoothing_clearance"), std::string("wall_distance"), "");
  EXPECT_EQ(p.smoothing_clearance, kClearanceOfWallDistance);
  assignParameter(p, *findParameter("turning_radius"), 2.5, "");
  EXPECT_EQ(p.turning_radius, 2.5);
}

TEST(ParameterSchema, ABoundByAnotherParameterNamesWhereEitherCameFrom) {
  PlannerParameters p;
  p.min_turning_radius = 2.0;
  try {
    checkParameters(p, {{"turning_radius", "lake.yaml:9"}});
    FAIL() << "no error";
  } catch (const InvalidInputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "lake.yaml:9: min_turning_radius = 2 is out of range: it must be in [0, "
              "turning_radius = 1] (m)");
  }
}

TEST(ParameterSchema, ConfigDefaultYamlIsTheSchemasOutput) {
  EXPECT_EQ(fileText("config/default.yaml"), defaultParametersYaml())
      << "regenerate it: coverage_tool parameters > config/default.yaml";
}

TEST(ParameterSchema, TheReferenceTableSaysWhatTheSchemaDeclares) {
  const auto rows = tableRows(fileText("docs/REFERENCE.md"), "## Parameters");
  const std::vector<ParameterDeclaration>& schema = parameterSchema();
  ASSERT_EQ(rows.size(), schema.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const ParameterDeclaration& d = schema[i];
    ASSERT_GE(rows[i].size(), 5u);
    EXPECT_EQ(rows[i][0], "`" + std::string(d.name) + "`") << "row " << i;
    EXPECT_EQ(rows[i][1], d.unit) << d.name;
    EXPECT_TRUE(sameDefault(d, rows[i][2])) << d.name << ": " << rows[i][2];
    EXPECT_EQ(rows[i][3], validValuesText(d)) << d.name;
  }
}

TEST(ParameterSchema, TheReadmeTableNamesEveryParameterWithItsDefault) {
  std::set<std::string> named;
  for (const auto& row : tableRows(fileText("README.md"), "## Parameters")) {
    ASSERT_GE(row.size(), 3u);
    std::vector<std::string> names, defaults;
    std::istringstream name_list(row[0]), default_list(row[1]);
    for (std::string name; std::getline(name_list, name, ',');) {
      names.push_back(withoutBackticks(trimmed(name)));
    }
    for (std::string value; std::getline(default_list, value, ',');) {
      defaults.push_back(trimmed(value));
    }
    for (std::size_t i = 0; i < names.size(); ++i) {
      const ParameterDeclaration* d = findParameter(names[i]);
      if (d == nullptr) continue;  // a node-only parameter
      named.insert(names[i]);
      ASSERT_EQ(defaults.size(), names.size()) << row[0];
      EXPECT_TRUE(sameDefault(*d, defaults[i])) << names[i] << ": " << defaults[i];
    }
  }
  for (const ParameterDeclaration& d : parameterSchema())
    EXPECT_EQ(named.count(d.name), 1u) << d.name;
}

}  // namespace
}  // namespace kinematic_coverage::core
