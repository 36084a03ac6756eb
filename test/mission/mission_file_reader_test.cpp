#include "coverage_system/mission/mission_file_reader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <variant>

#include "coverage_system/parameters/parameter_schema.h"
#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/validation/polygon_cleaner.h"
#include "polygon_coverage_ros_bridge/validation/polygon_validator.h"

namespace kinematic_coverage::core {
namespace {

const char* const kMission = R"(frame_id: lake
polygon:
  hull: [[0, 0], [30, 0], [30, 30], [0, 30]]
  holes:
    - [[8, 8], [12, 8], [12, 12], [8, 12]]
    - [[20, 20], [22, 20], [21, 22]]
start: [1, 1.5]
goal: [29, 29]
turning_radius: 2.0
)";

std::string errorOf(const std::string& yaml, const std::vector<std::string>& overrides = {}) {
  try {
    MissionFileReader().parse(yaml, "m.yaml", overrides);
  } catch (const InvalidInputError& error) {
    return error.what();
  }
  return "";
}

/// The example mission with `line` replacing the line that starts like it.
std::string missionWith(const std::string& key, const std::string& line) {
  std::istringstream in(kMission);
  std::string out, current;
  while (std::getline(in, current)) out += (current.rfind(key, 0) == 0 ? line : current) + "\n";
  return out;
}

TEST(MissionFileReader, ReadsEveryPartOfAMission) {
  const Mission mission = MissionFileReader().parse(kMission, "m.yaml");
  EXPECT_EQ(mission.frame_id, "lake");
  ASSERT_EQ(mission.polygon.hull.size(), 4u);
  EXPECT_EQ(mission.polygon.hull[1], Point2(30, 0));
  ASSERT_EQ(mission.polygon.holes.size(), 2u);
  EXPECT_EQ(mission.polygon.holes[1][2], Point2(21, 22));
  EXPECT_EQ(mission.start, Point2(1, 1.5));
  EXPECT_EQ(mission.goal, Point2(29, 29));
  EXPECT_EQ(mission.parameters.turning_radius, 2.0);
  EXPECT_EQ(mission.parameters.v_max, PlannerParameters{}.v_max);
}

TEST(MissionFileReader, DefaultsFrameAndHoles) {
  const Mission mission = MissionFileReader().parse(
      "polygon: {hull: [[0, 0], [1, 0], [0, 1]]}\nstart: [0, 0]\ngoal: [0, 0]\n", "m.yaml");
  EXPECT_EQ(mission.frame_id, "map");
  EXPECT_TRUE(mission.polygon.holes.empty());
}

TEST(MissionFileReader, ReadsEveryParameterKey) {
  const std::string base = missionWith("turning_radius", "");
  const std::vector<std::pair<std::string, std::string>> values = {
      {"decomposition_type", "trapezoidal"},
      {"cell_joining", "longest_overlap"},
      {"cost_function", "distance"},
      {"v_max", "1.5"},
      {"a_max", "0.7"},
      {"yaw_rate_max", "0.9"},
      {"wall_distance", "0"},
      {"offset_parts", "largest"},
      {"gap_clearance", "0.35"},
      {"sensor_model", "line"},
      {"lateral_fov", "1.1"},
      {"onward_fov", "0.3"},
      {"lateral_footprint", "4.5"},
      {"sensor_distance", "7"},
      {"lateral_overlap", "0.25"},
      {"coverage_repair", "true"},
      {"smoothing", "false"},
      {"turning_radius", "3.5"},
      {"smoothing_strategy", "local"},
      {"min_turning_radius", "1.5"},
      {"max_turning_radius", "4"},
      {"coverage_preserving", "true"},
      {"coverage_safe_area", "free"},
      {"segment_sampling_distance", "0.25"},
      {"arc_sampling_distance", "0.05"},
      {"rotation_sampling_angle", "0.1"},
      {"turn_curve", "clothoid"},
      {"curvature_rate_max", "3.5"},
      {"replanning_method", "convex_hull"},
      {"replanning_sliver_fraction", "0.3"},
      {"boundary_simplification", "0.05"},
      {"replanning_min_area", "2.5"},
      {"replanning_simplify_tolerance", "0.25"},
      {"alpha", "6"},
      {"vehicle_model", "kinematic"},
      {"mass", "20"},
      {"added_mass_surge", "6"},
      {"added_mass_sway", "13"},
      {"inertia_yaw", "0.5"},
      {"added_inertia_yaw", "0.2"},
      {"damping_surge_linear", "4"},
      {"damping_sway_linear", "7"},
      {"damping_yaw_linear", "0.1"},
      {"damping_surge_quadratic", "18"},
      {"damping_sway_quadratic", "22"},
      {"damping_yaw_quadratic", "1.5"},
      {"thrust_max", "80"},
      {"yaw_torque_max", "20"},
      {"surge_loop_gain", "4"},
      {"yaw_rate_loop_gain", "3"},
      {"yaw_gain", "3"},
      {"position_gain", "0.8"},
      {"position_tolerance", "0.2"},
      {"yaw_tolerance", "0.1"},
      {"current_x", "-0.05"},
      {"current_y", "0.15"},
      {"smoothing_clearance", "0.25"},
      {"current_sigma", "0.02"},
      {"current_time_constant", "30"},
      {"navigation_sigma", "0.1"},
      {"navigation_time_constant", "1.5"},
      {"disturbance_seed", "7"},
      {"sim_dt", "0.2"},
      {"sim_time_limit", "600"}};
  std::string yaml = base;
  for (const auto& [key, value] : values) yaml += key + ": " + value + "\n";
  const PlannerParameters p = MissionFileReader().parse(yaml, "m.yaml").parameters;
  EXPECT_EQ(p.decomposition_type, "trapezoidal");
  EXPECT_EQ(p.cell_joining, "longest_overlap");
  EXPECT_EQ(p.cost_function, "distance");
  EXPECT_EQ(p.v_max, 1.5);
  EXPECT_EQ(p.a_max, 0.7);
  EXPECT_EQ(p.yaw_rate_max, 0.9);
  EXPECT_EQ(p.wall_distance, 0.0);
  EXPECT_EQ(p.offset_parts, "largest");
  EXPECT_EQ(p.sensor_model, "line");
  EXPECT_EQ(p.lateral_fov, 1.1);
  EXPECT_EQ(p.onward_fov, 0.3);
  EXPECT_EQ(p.replanning_sliver_fraction, 0.3);
  EXPECT_EQ(p.boundary_simplification, 0.05);
  EXPECT_EQ(p.replanning_min_area, 2.5);
  EXPECT_EQ(p.replanning_simplify_tolerance, 0.25);
  EXPECT_EQ(p.lateral_footprint, 4.5);
  EXPECT_EQ(p.sensor_distance, 7.0);
  EXPECT_EQ(p.lateral_overlap, 0.25);
  EXPECT_TRUE(p.coverage_repair);
  EXPECT_FALSE(p.smoothing);
  EXPECT_EQ(p.turning_radius, 3.5);
  EXPECT_EQ(p.smoothing_strategy, "local");
  EXPECT_EQ(p.min_turning_radius, 1.5);
  EXPECT_EQ(p.max_turning_radius, 4.0);
  EXPECT_TRUE(p.coverage_preserving);
  EXPECT_EQ(p.coverage_safe_area, "free");
  EXPECT_EQ(p.segment_sampling_distance, 0.25);
  EXPECT_EQ(p.arc_sampling_distance, 0.05);
  EXPECT_EQ(p.rotation_sampling_angle, 0.1);
  EXPECT_EQ(p.turn_curve, "clothoid");
  EXPECT_EQ(p.curvature_rate_max, 3.5);
  EXPECT_EQ(p.replanning_method, "convex_hull");
  EXPECT_EQ(p.alpha, 6.0);
  EXPECT_EQ(p.vehicle_model, "kinematic");
  EXPECT_EQ(p.mass, 20.0);
  EXPECT_EQ(p.added_mass_surge, 6.0);
  EXPECT_EQ(p.added_mass_sway, 13.0);
  EXPECT_EQ(p.inertia_yaw, 0.5);
  EXPECT_EQ(p.added_inertia_yaw, 0.2);
  EXPECT_EQ(p.damping_surge_linear, 4.0);
  EXPECT_EQ(p.damping_sway_linear, 7.0);
  EXPECT_EQ(p.damping_yaw_linear, 0.1);
  EXPECT_EQ(p.damping_surge_quadratic, 18.0);
  EXPECT_EQ(p.damping_sway_quadratic, 22.0);
  EXPECT_EQ(p.damping_yaw_quadratic, 1.5);
  EXPECT_EQ(p.thrust_max, 80.0);
  EXPECT_EQ(p.yaw_torque_max, 20.0);
  EXPECT_EQ(p.surge_loop_gain, 4.0);
  EXPECT_EQ(p.yaw_rate_loop_gain, 3.0);
  EXPECT_EQ(p.yaw_gain, 3.0);
  EXPECT_EQ(p.position_gain, 0.8);
  EXPECT_EQ(p.position_tolerance, 0.2);
  EXPECT_EQ(p.yaw_tolerance, 0.1);
  EXPECT_EQ(p.current_x, -0.05);
  EXPECT_EQ(p.current_y, 0.15);
  EXPECT_EQ(p.smoothing_clearance, 0.25);
  EXPECT_EQ(p.gap_clearance, 0.35);
  EXPECT_EQ(p.current_sigma, 0.02);
  EXPECT_EQ(p.current_time_constant, 30.0);
  EXPECT_EQ(p.navigation_sigma, 0.1);
  EXPECT_EQ(p.navigation_time_constant, 1.5);
  EXPECT_EQ(p.disturbance_seed, 7.0);
  EXPECT_EQ(p.sim_dt, 0.2);
  EXPECT_EQ(p.sim_time_limit, 600.0);
}

/// A value of `declaration` other than its default that passes the checks with every other
/// parameter at its default.
std::string otherValidValue(const ParameterDeclaration& declaration) {
  if (!declaration.choices.empty()) {
    for (const std::string& choice : declaration.choices) {
      if (choice != std::get<std::string>(declaration.default_value)) return choice;
    }
  }
  if (const bool* flag = std::get_if<bool>(&declaration.default_value)) {
    return *flag ? "false" : "true";
  }
  const double value = std::get<double>(declaration.default_value);
  for (const double candidate :
       {value * 1.25, value * 0.8, value + 0.125, value - 0.125, 0.5, 1.0, 2.0, 0.0}) {
    PlannerParameters p;
    try {
      assignParameter(p, declaration, candidate, "");
      checkParameters(p);
      if (candidate != value) return formatRoundTrip(candidate);
    } catch (const InvalidInputError&) {
    }
  }
  ADD_FAILURE() << "no other valid value of " << declaration.name;
  return "";
}

// Every declared parameter is a mission file key that sets its own value and no other.
TEST(MissionFileReader, EveryDeclaredParameterIsAKeyThatSetsItAlone) {
  const std::string base = missionWith("turning_radius", "");
  const PlannerParameters defaults;
  for (const ParameterDeclaration& declaration : parameterSchema()) {
    SCOPED_TRACE(declaration.name);
    const std::string value = otherValidValue(declaration);
    const PlannerParameters p = MissionFileReader()
                                    .parse(base + declaration.name + ": " + value + "\n", "m.yaml")
                                    .parameters;
    EXPECT_EQ(MissionFileReader::parameterText(p, declaration.name), value);
    for (const ParameterDeclaration& other : parameterSchema()) {
      if (&other == &declaration) continue;
      EXPECT_EQ(MissionFileReader::parameterText(p, other.name),
                MissionFileReader::parameterText(defaults, other.name))
          << other.name;
    }
  }
}

TEST(MissionFileReader, AppliesOverridesAfterTheFile) {
  const Mission mission = MissionFileReader().parse(
      kMission, "m.yaml", {"turning_radius=2.5", "smoothing=no", "cost_function=waypoints"});
  EXPECT_EQ(mission.parameters.turning_radius, 2.5);
  EXPECT_FALSE(mission.parameters.smoothing);
  EXPECT_EQ(mission.parameters.cost_function, "waypoints");
  EXPECT_EQ(errorOf(kMission, {"turnig_radius=2"}),
            "--set turnig_radius=2: unknown parameter 'turnig_radius'");
  EXPECT_EQ(errorOf(kMission, {"turning_radius"}), "--set turning_radius: expected name=value");
  EXPECT_EQ(errorOf(kMission, {"turning_radius=abc"}),
            "--set turning_radius=abc: turning_radius: the value 'abc' is not a number");
  EXPECT_EQ(errorOf(kMission, {"turning_radius="}),
            "--set turning_radius=: turning_radius: the value must be a number, not nothing");
  EXPECT_EQ(errorOf(kMission, {"smoothing=maybe"}),
            "--set smoothing=maybe: smoothing: the value 'maybe' is not true or false");
  EXPECT_EQ(errorOf(kMission, {"turning_radius=-1"}),
            "--set turning_radius=-1: turning_radius = -1 is out of range: it must be a finite "
            "number > 0 (m)");
}

TEST(MissionFileReader, RejectsUnknownAndDuplicateKeys) {
  EXPECT_EQ(errorOf(missionWith("turning_radius", "turnig_radius: 2")),
            "m.yaml:9: turnig_radius: unknown key (a mission has frame_id, polygon, start, "
            "goal and the parameters of config/default.yaml)");
  EXPECT_EQ(errorOf("polygon:\n  hull: [[0, 0], [1, 0], [0, 1]]\n  hole: []\n"),
            "m.yaml:3: polygon.hole: unknown key (a polygon has hull and holes)");
  EXPECT_EQ(errorOf(std::string(kMission) + "turning_radius: 3\n"),
            "m.yaml:10: turning_radius: the key appears twice");
}

TEST(MissionFileReader, RejectsMissingParts) {
  EXPECT_EQ(errorOf(missionWith("goal", "")), "m.yaml: the goal is missing");
  EXPECT_EQ(errorOf(missionWith("start", "")), "m.yaml: the start is missing");
  EXPECT_EQ(errorOf("start: [0, 0]\ngoal: [0, 0]\n"), "m.yaml: the polygon is missing");
  EXPECT_EQ(errorOf("polygon: {holes: []}\nstart: [0, 0]\ngoal: [0, 0]\n"),
            "m.yaml:1: polygon: the hull is missing");
  EXPECT_EQ(errorOf(""), "m.yaml: the file is empty");
  EXPECT_EQ(errorOf("- 1\n- 2\n"), "m.yaml: the file must be a map of keys, not a list");
}

TEST(MissionFileReader, RejectsWrongShapes) {
  EXPECT_EQ(errorOf(missionWith("start", "start: [1, 2, 3]")),
            "m.yaml:7: start: a point must be a list of 2 numbers [x, y], not a list of 3 items");
  EXPECT_EQ(errorOf(missionWith("  hull", "  hull: 5")),
            "m.yaml:3: polygon.hull: a ring must be a list of [x, y] points, not '5'");
  EXPECT_EQ(errorOf(missionWith("  hull", "  hull: {a: 1}")),
            "m.yaml:3: polygon.hull: a ring must be a list of [x, y] points, not a map");
  EXPECT_EQ(errorOf(missionWith("    - [[20", "    - [[20, 20], [22, 20], [21, 22], [1, 2, 3]]")),
            "m.yaml:6: polygon.holes[1][3]: a point must be a list of 2 numbers [x, y], not a "
            "list of 3 items");
  EXPECT_EQ(errorOf("polygon:\n  hull: [[0, 0], [1, 0], [0, 1]]\n  holes: 3\n"),
            "m.yaml:3: polygon.holes: must be a list of rings, not '3'");
  EXPECT_EQ(errorOf("frame_id: map\npolygon: [1, 2]\n"),
            "m.yaml:2: polygon: must be a map with hull and holes, not a list");
  EXPECT_EQ(errorOf(missionWith("frame_id", "frame_id: [a]")),
            "m.yaml:1: frame_id: must be a frame name, not a list");
}

TEST(MissionFileReader, RejectsNonNumericAndNonFiniteCoordinates) {
  EXPECT_EQ(errorOf(missionWith("    - [[20", "    - [[20, 20], [22, 20], [21, 22], [abc, 1]]")),
            "m.yaml:6: polygon.holes[1][3]: the x coordinate 'abc' is not a number");
  EXPECT_EQ(errorOf(missionWith("goal", "goal: [1, .nan]")),
            "m.yaml:8: goal: the y coordinate '.nan' is not finite");
  EXPECT_EQ(errorOf(missionWith("  hull", "  hull: [[0, 0], [-.inf, 0], [0, 1]]")),
            "m.yaml:3: polygon.hull[1]: the x coordinate '-.inf' is not finite");
  EXPECT_EQ(errorOf(missionWith("  hull", "  hull: [[0, 0], [[1], 0], [0, 1]]")),
            "m.yaml:3: polygon.hull[1]: the x coordinate must be a number, not a list");
  EXPECT_EQ(errorOf(missionWith("goal", "goal: [1, 1e300]")),
            "m.yaml:8: goal: the y coordinate 1e+300 exceeds the limit of +-100000000 m");
}

TEST(MissionFileReader, RejectsBadYaml) {
  const std::string message = errorOf("polygon: [[0, 0]\nstart: [0, 0]\n");
  EXPECT_EQ(message.rfind("m.yaml:", 0), 0u) << message;
  EXPECT_NE(message.find("not valid YAML"), std::string::npos) << message;
  const std::string deep = errorOf("polygon: " + std::string(100000, '[') + "\n");
  EXPECT_NE(deep.find("not valid YAML"), std::string::npos) << deep;
}

TEST(MissionFileReader, EnforcesTheSizeLimits) {
  std::string holes = "polygon:\n  hull: [[0, 0], [10, 0], [0, 10]]\n  holes:\n";
  for (int i = 0; i <= 5000; ++i) holes += "    - [[1, 1], [2, 1], [1, 2]]\n";
  EXPECT_EQ(errorOf(holes + "start: [0, 0]\ngoal: [0, 0]\n"),
            "m.yaml:4: polygon.holes: 5001 holes, more than the limit of 5000");
  std::string vertices = "polygon:\n  hull: [";
  for (int i = 0; i <= 100000; ++i) vertices += "[" + std::to_string(i) + ", 0],";
  vertices += "[0, 1]]\nstart: [0, 0]\ngoal: [0, 0]\n";
  EXPECT_EQ(errorOf(vertices),
            "m.yaml:2: polygon.hull: the polygon has more than 100000 vertices in total, the "
            "limit");
}

TEST(MissionFileReader, RejectsParametersOutOfRange) {
  EXPECT_EQ(errorOf(missionWith("turning_radius", "lateral_overlap: 1.0")),
            "m.yaml:9: lateral_overlap = 1 is out of range: it must be in [0, 1)");
  EXPECT_EQ(errorOf(missionWith("turning_radius", "lateral_fov: 3.2")),
            "m.yaml:9: lateral_fov = 3.2 is out of range: it must be in (0, pi) (rad)");
  EXPECT_EQ(errorOf(missionWith("turning_radius", "sensor_distance: 0")),
            "m.yaml:9: sensor_distance = 0 is out of range: it must be a finite number > 0 (m)");
  EXPECT_EQ(errorOf(missionWith("turning_radius", "decomposition_type: grid")),
            "m.yaml:9: decomposition_type = 'grid' is not one of: boustrophedon, trapezoidal");
  EXPECT_EQ(errorOf(missionWith("turning_radius", "turning_radius: fast")),
            "m.yaml:9: turning_radius: the value 'fast' is not a number");
  EXPECT_EQ(errorOf(missionWith("turning_radius", "smoothing: 1.5")),
            "m.yaml:9: smoothing: the value '1.5' is not true or false");
  EXPECT_EQ(errorOf(missionWith("turning_radius", "smoothing_clearance: -1")),
            "m.yaml:9: smoothing_clearance = -1 is out of range: it must be a finite number >= 0 "
            "(m), or the word wall_distance");
  EXPECT_EQ(errorOf(missionWith("turning_radius", "smoothing_clearance: wall")),
            "m.yaml:9: smoothing_clearance: the value 'wall' is not a number or the word "
            "wall_distance");
}

TEST(MissionFileReader, ReadsTheWordWallDistanceAsAClearance) {
  // smoothing_clearance defaults to the wall distance, written as that word; it reads back
  // as itself, and a number replaces it.
  const Mission word = MissionFileReader().parse(kMission, "m.yaml", {"wall_distance=2.5"});
  EXPECT_EQ(word.parameters.smoothing_clearance, kClearanceOfWallDistance);
  EXPECT_EQ(MissionFileReader::parameterText(word.parameters, "smoothing_clearance"),
            "wall_distance");
  EXPECT_EQ(smoothingClearanceOf(word.parameters), 2.5);
  const Mission number = MissionFileReader().parse(kMission, "m.yaml", {"smoothing_clearance=0.3"});
  EXPECT_EQ(smoothingClearanceOf(number.parameters), 0.3);
  const Mission back =
      MissionFileReader().parse(missionWith("turning_radius", "smoothing_clearance: wall_distance"),
                                "m.yaml", {"wall_distance=0.7"});
  EXPECT_EQ(smoothingClearanceOf(back.parameters), 0.7);
  // gap_clearance likewise.
  EXPECT_EQ(word.parameters.gap_clearance, kClearanceOfWallDistance);
  EXPECT_EQ(MissionFileReader::parameterText(word.parameters, "gap_clearance"), "wall_distance");
  EXPECT_EQ(gapClearanceOf(word.parameters), 2.5);
  EXPECT_EQ(gapClearanceOf(
                MissionFileReader().parse(kMission, "m.yaml", {"gap_clearance=0.4"}).parameters),
            0.4);
}

TEST(MissionFileReader, ReadsFilesAndReportsMissingOnes) {
  const std::string dir = ::testing::TempDir() + "/mission_reader";
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/m.yaml") << kMission;
  EXPECT_EQ(MissionFileReader().read(dir + "/m.yaml").frame_id, "lake");
  try {
    MissionFileReader().read(dir + "/none.yaml");
    FAIL();
  } catch (const InvalidInputError& error) {
    EXPECT_EQ(std::string(error.what()), dir + "/none.yaml: no such file");
  }
  EXPECT_THROW(MissionFileReader().read(dir), InvalidInputError);
}

TEST(MissionFileReader, ReadsUpdatedPolygons) {
  const PolygonWithHoles polygon = MissionFileReader().parseUpdatedPolygon(
      "frame_id: map\npolygon:\n  hull: [[0, 0], [5, 0], [5, 5]]\n", "u.yaml");
  EXPECT_EQ(polygon.hull.size(), 3u);
  EXPECT_THROW(MissionFileReader().parseUpdatedPolygon("start: [0, 0]\n", "u.yaml"),
               InvalidInputError);
  EXPECT_THROW(MissionFileReader().parseUpdatedPolygon("frame_id: map\n", "u.yaml"),
               InvalidInputError);
}

TEST(DefaultYaml, EqualsTheBuiltInDefaults) {
  const std::string path = std::string(KC_SOURCE_DIR) + "/config/default.yaml";
  const PlannerParameters loaded = MissionFileReader().readParameters(path);
  const PlannerParameters defaults;
  for (const std::string& name : MissionFileReader::parameterNames()) {
    EXPECT_EQ(MissionFileReader::parameterText(loaded, name),
              MissionFileReader::parameterText(defaults, name))
        << name;
  }
  // Every parameter is written out, not just defaulted.
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  for (const std::string& name : MissionFileReader::parameterNames()) {
    EXPECT_NE(text.str().find("\n" + name + ": "), std::string::npos) << name;
  }
}

TEST(ThesisYaml, DiffersFromTheDefaultsOnlyWhereTheDefaultsGoBeyondTheThesis) {
  // The README's "Defaults that differ from the thesis" lists these, with the reasons.
  const std::map<std::string, std::string> thesis_values = {
      {"cell_joining", "critical_points"}, {"smoothing_strategy", "local"},
      {"coverage_repair", "false"},        {"boundary_simplification", "0"},
      {"offset_miter_limit", "1000"},      {"smoothing_clearance", "0"},
      {"controller", "setpoint"},          {"braking", "false"}};
  const PlannerParameters thesis =
      MissionFileReader().readParameters(std::string(KC_SOURCE_DIR) + "/config/thesis.yaml");
  const PlannerParameters defaults;
  for (const std::string& name : MissionFileReader::parameterNames()) {
    const auto differing = thesis_values.find(name);
    EXPECT_EQ(MissionFileReader::parameterText(thesis, name),
              differing != thesis_values.end() ? differing->second
                                               : MissionFileReader::parameterText(defaults, name))
        << name;
  }
  // The thesis's lake experiments (Chapter 4): boustrophedon, time cost, 1 m wall offset,
  // 40 % overlap, 3 m sensor distance, FOV 2.27 and 0.52 rad, 1 m turning radius, sampling
  // 0.5 m on segments and 0.1 m on arcs.
  EXPECT_EQ(thesis.decomposition_type, "boustrophedon");
  EXPECT_EQ(thesis.cell_joining, "critical_points");
  EXPECT_EQ(thesis.cost_function, "time");
  EXPECT_EQ(thesis.wall_distance, 1.0);
  EXPECT_EQ(thesis.lateral_overlap, 0.4);
  EXPECT_EQ(thesis.sensor_distance, 3.0);
  EXPECT_EQ(thesis.lateral_fov, 2.27);
  EXPECT_EQ(thesis.onward_fov, 0.52);
  EXPECT_EQ(thesis.turning_radius, 1.0);
  EXPECT_EQ(thesis.segment_sampling_distance, 0.5);
  EXPECT_EQ(thesis.arc_sampling_distance, 0.1);
}

TEST(MissionFileReader, MissionKeysAndOverridesApplyOverAParameterFile) {
  PlannerParameters base;
  base.smoothing_strategy = "local";
  base.turning_radius = 2.0;
  base.v_max = 0.7;
  const Mission mission = MissionFileReader().parse(
      "polygon:\n  hull: [[0, 0], [10, 0], [10, 10], [0, 10]]\nstart: [1, 1]\n"
      "goal: [9, 9]\nturning_radius: 1.5\n",
      "m.yaml", {"v_max=0.9"}, base);
  EXPECT_EQ(mission.parameters.smoothing_strategy, "local");  // the parameter file's
  EXPECT_EQ(mission.parameters.turning_radius, 1.5);          // the mission file's
  EXPECT_EQ(mission.parameters.v_max, 0.9);                   // --set's
  EXPECT_THROW(MissionFileReader::parameterText(base, "no_such_parameter"), InvalidInputError);
}

TEST(ShippedMissions, LoadValidateAndClean) {
  std::vector<std::string> paths;
  for (const std::string dir : {std::string(KC_SOURCE_DIR) + "/config/missions",
                                std::string(KC_BENCH_DATA_DIR) + "/pcp_polygons"}) {
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      if (entry.path().extension() == ".yaml") paths.push_back(entry.path().string());
    }
  }
  EXPECT_GE(paths.size(), 10u);
  for (const std::string& path : paths) {
    SCOPED_TRACE(path);
    const Mission mission = MissionFileReader().read(path);
    const PolygonValidator validator;
    EXPECT_NO_THROW(validator.validate(mission.polygon));
    EXPECT_NO_THROW(validator.validateEndpoint("start", mission.start, mission.polygon));
    EXPECT_NO_THROW(PolygonCleaner().clean(mission.polygon));
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
