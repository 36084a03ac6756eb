// Runs the coverage_tool binary on mission files written to a temporary directory and
// checks what docs/REFERENCE.md promises: exit status, one stderr line for invalid
// input, the files written.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "coverage_system/mission/mission_frame.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace {

struct ToolRun {
  int exit_status = -1;
  std::string out;
  std::vector<std::string> err_lines;
};

std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) result.push_back(line);
  return result;
}

std::string scratchDir() {
  const std::string dir = ::testing::TempDir() + "/coverage_tool_test";
  std::filesystem::create_directories(dir);
  return dir;
}

/// Runs coverage_tool with `args` (shell words, already quoted where needed).
ToolRun runTool(const std::string& args) {
  const std::string out = scratchDir() + "/stdout.txt";
  const std::string err = scratchDir() + "/stderr.txt";
  const std::string command =
      std::string("'") + KC_TOOL_PATH + "' " + args + " >'" + out + "' 2>'" + err + "'";
  const int status = std::system(command.c_str());
  ToolRun run;
  run.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = readText(out);
  run.err_lines = lines(readText(err));
  return run;
}

std::string writeMission(const std::string& name, const std::string& yaml) {
  const std::string path = scratchDir() + "/" + name + ".yaml";
  std::ofstream(path) << yaml;
  return path;
}

std::string mission(const std::string& polygon, const std::string& extra = "",
                    const std::string& start = "[1, 1]", const std::string& goal = "[29, 29]") {
  return "frame_id: map\npolygon:\n" + polygon + "start: " + start + "\ngoal: " + goal + "\n" +
         extra;
}

const char* const kSquare = "  hull: [[0, 0], [30, 0], [30, 30], [0, 30]]\n";
const char* const kSquareWithHole =
    "  hull: [[0, 0], [30, 0], [30, 30], [0, 30]]\n"
    "  holes: [[[8, 8], [12, 8], [12, 12], [8, 12]]]\n";

/// Expects exit 2 and exactly one stderr line "error: ..." containing `expected`.
void expectInvalid(const std::string& args, const std::string& expected) {
  SCOPED_TRACE(args);
  const ToolRun run = runTool(args);
  EXPECT_EQ(run.exit_status, 2);
  ASSERT_EQ(run.err_lines.size(), 1u) << run.out;
  EXPECT_EQ(run.err_lines[0].rfind("error: ", 0), 0u) << run.err_lines[0];
  EXPECT_NE(run.err_lines[0].find(expected), std::string::npos) << run.err_lines[0];
}

void expectInvalidMission(const std::string& yaml, const std::string& expected,
                          const std::string& options = "") {
  const std::string path = writeMission("invalid", yaml);
  const std::string out_dir = scratchDir() + "/invalid_out";
  std::filesystem::remove_all(out_dir);
  expectInvalid("plan '" + path + "' --out '" + out_dir + "' " + options, expected);
  EXPECT_FALSE(std::filesystem::exists(out_dir + "/waypoints.csv"));
}

TEST(CoverageTool, RejectsEachInvalidInputClassWithOneLine) {
  expectInvalidMission(mission("  hull: [[0, 0], [30, 0]]\n"),
                       "hull has 2 distinct vertices: a ring needs at least 3");
  expectInvalidMission(mission("  hull: [[0, 0], [10, 10], [20, 20]]\n"), "hull has zero area");
  expectInvalidMission(mission("  hull: [[0, 0], [30, 30], [30, 0], [0, 30]]\n"),
                       "hull is self-intersecting: edge 0 (vertices 0-1) and edge 2 (vertices "
                       "2-3) meet at (15, 15)");
  expectInvalidMission(
      mission("  hull: [[0, 0], [30, 0], [30, 30], [0, 30]]\n"
              "  holes: [[[8, 8], [12, 8], [12, 12], [8, 12]], [[5, 5], [6, 5], [x, 6]]]\n"),
      "polygon.holes[1][2]: the x coordinate 'x' is not a number");
  expectInvalidMission(mission(kSquare, "", "[.inf, 1]"),
                       "start: the x coordinate '.inf' is not finite");
  expectInvalidMission(mission("  hull: [[0, 0], [30, 0], [30, 30], [0, 30]]\n"
                               "  holes: [[[40, 40], [42, 40], [42, 42]]]\n"),
                       "hole 0 lies entirely outside the hull");
  expectInvalidMission(mission(kSquareWithHole, "", "[10, 10]"),
                       "start (10, 10) lies inside hole 0");
  expectInvalidMission(mission(kSquareWithHole, "", "[1, 1]", "[9, 11]"),
                       "goal (9, 11) lies inside hole 0");
  expectInvalidMission(mission(kSquare, "turning_radius: 0\n"),
                       "turning_radius = 0 is out of range: it must be a finite number > 0");
  expectInvalidMission(mission(kSquare, "lateral_overlap: 1\n"),
                       "lateral_overlap = 1 is out of range: it must be in [0, 1)");
  expectInvalidMission(mission(kSquare, "onward_fov: 3.5\n"),
                       "onward_fov = 3.5 is out of range: it must be in (0, pi) (rad)");
  expectInvalidMission(mission(kSquare, "turnig_radius: 2\n"), "turnig_radius: unknown key");
  expectInvalidMission(mission(kSquare), "--set x=1: unknown parameter 'x'",
                       "--set x=1 --set sensor_distance=-3");
  expectInvalidMission(mission(kSquare), "sensor_distance = -3 is out of range",
                       "--set sensor_distance=-3");
  expectInvalidMission(mission("  hull: [[0, 0], [30, 0], [30, 30], [0, 30]]\n"
                               "  holes: [[[-1, 10], [31, 10], [31, 12], [-1, 12]]]\n"),
                       "the holes split the free area into 2 disconnected parts");
  std::string many_holes = "  hull: [[0, 0], [30, 0], [30, 30], [0, 30]]\n  holes:\n";
  for (int i = 0; i <= 5000; ++i) many_holes += "    - [[1, 1], [2, 1], [1, 2]]\n";
  expectInvalidMission(mission(many_holes), "5001 holes, more than the limit of 5000");
  expectInvalidMission("polygon: [[[\n", "not valid YAML");
}

TEST(CoverageTool, RejectsBadCommandLines) {
  expectInvalid("", "no command given");
  expectInvalid("frobnicate", "unknown command 'frobnicate'");
  expectInvalid("plan", "no mission file given");
  expectInvalid("plan '" + writeMission("ok", mission(kSquare)) + "'", "--out DIR is required");
  expectInvalid("plan '" + writeMission("ok", mission(kSquare)) + "' --out", "--out needs a value");
  expectInvalid("plan a.yaml b.yaml --out x", "one mission file expected");
  expectInvalid("plan a.yaml --bogus --out x", "unknown option '--bogus'");
  expectInvalid("plan '" + scratchDir() + "/missing.yaml' --out x", "missing.yaml: no such file");
  expectInvalid("replan m.yaml", "--updated UPDATED.yaml is required");
  expectInvalid("simulate m.yaml", "--trajectory FILE.csv is required");
}

TEST(CoverageTool, PrintsHelp) {
  const ToolRun run = runTool("--help");
  EXPECT_EQ(run.exit_status, 0);
  EXPECT_NE(run.out.find("plan MISSION.yaml --out DIR"), std::string::npos);
  const ToolRun plan_help = runTool("plan --help");
  EXPECT_EQ(plan_help.exit_status, 0);
  EXPECT_NE(plan_help.out.find("--set name=value"), std::string::npos);
}

/// The number of `key` in a flat metrics.json line.
double metric(const std::string& json, const std::string& key) {
  const std::size_t at = json.find("\"" + key + "\": ");
  if (at == std::string::npos) return std::nan("");
  return std::stod(json.substr(at + key.size() + 4));
}

TEST(CoverageTool, PlansTheLakeMissionAndWritesItsFiles) {
  const std::string out_dir = scratchDir() + "/lake_out";
  std::filesystem::remove_all(out_dir);
  const ToolRun run =
      runTool("plan '" + std::string(KC_SOURCE_DIR) + "/config/missions/lake_30x30.yaml' --out '" +
              out_dir + "' --set lateral_overlap=0.5");
  ASSERT_EQ(run.exit_status, 0);
  const std::vector<std::string> out_lines = lines(run.out);
  ASSERT_FALSE(out_lines.empty());
  EXPECT_EQ(out_lines.back(), "wrote " + out_dir + "/waypoints.csv " + out_dir +
                                  "/trajectory.csv " + out_dir + "/metrics.json " + out_dir +
                                  "/plot.png");
  // The lake needs no cleaning: nothing on stderr.
  EXPECT_TRUE(run.err_lines.empty()) << run.err_lines.front();
  // One progress line per stage, in order, on stdout.
  std::size_t previous = 0;
  for (const std::string stage :
       {"load: ", "validate: ", "clean: ", "offset: ", "decompose: ", "sweeps: ", "transitions: ",
        "solve: ", "path: ", "smooth: ", "coverage: ", "write: "}) {
    const auto it = std::find_if(out_lines.begin(), out_lines.end(), [&](const std::string& line) {
      return line.rfind(stage, 0) == 0;
    });
    ASSERT_NE(it, out_lines.end()) << stage;
    EXPECT_GE(static_cast<std::size_t>(it - out_lines.begin()), previous) << stage;
    previous = static_cast<std::size_t>(it - out_lines.begin());
  }
  EXPECT_EQ(readText(out_dir + "/plot.png").substr(0, 8), "\x89PNG\r\n\x1a\n");
  const std::vector<std::string> trajectory = lines(readText(out_dir + "/trajectory.csv"));
  ASSERT_GE(trajectory.size(), 3u);
  EXPECT_EQ(trajectory[0], "t,x,y,yaw,kind");

  const std::vector<std::string> rows = lines(readText(out_dir + "/waypoints.csv"));
  ASSERT_GE(rows.size(), 3u);
  EXPECT_EQ(rows[0], "x,y,yaw");
  for (std::size_t i = 1; i < rows.size(); ++i) {
    double x = 0, y = 0, yaw = 0;
    char comma1 = 0, comma2 = 0;
    std::istringstream row(rows[i]);
    ASSERT_TRUE(row >> x >> comma1 >> y >> comma2 >> yaw) << rows[i];
    EXPECT_GT(yaw, -M_PI);
    EXPECT_LE(yaw, M_PI);
  }
  const std::string json = readText(out_dir + "/metrics.json");
  EXPECT_EQ(metric(json, "waypoint_count"), static_cast<double>(rows.size() - 1));
  for (const std::string key : {"planning_time_s", "cells", "path_length_m", "time_cost_s",
                                "trajectory_length_m", "traversal_time_s", "max_curvature",
                                "min_obstacle_clearance_m", "turns_total", "turns_smoothed"}) {
    EXPECT_GT(metric(json, key), 0.0) << key << " in " << json;
  }
  EXPECT_EQ(metric(json, "turns_inner") + metric(json, "turns_outer_bisector") +
                metric(json, "turns_outer_tangent") + metric(json, "turns_reverse_curve"),
            metric(json, "turns_smoothed"))
      << json;
  EXPECT_EQ(metric(json, "turns_sharp"),
            metric(json, "turns_total") - metric(json, "turns_smoothed"))
      << json;
  EXPECT_NE(json.find("\"gtsp_time_capped\": false"), std::string::npos) << json;
  // With 50 % overlap the lake's trajectory sees nearly all of it.
  EXPECT_GE(metric(json, "coverage_percent"), 99.9) << json;
  EXPECT_LE(metric(json, "coverage_percent"), 100.0) << json;
  EXPECT_DOUBLE_EQ(metric(json, "coverage_loss_percent"), 100.0 - metric(json, "coverage_percent"));
  EXPECT_GE(metric(json, "reachable_coverage_percent"), 99.9) << json;
  EXPECT_LE(metric(json, "reachable_coverage_percent"), 100.0) << json;
  // 99.9 % of the lake's reachable area (about 700 m^2) leaves at most 0.7 m^2 unseen; the
  // corners of the 1 m wall band lie beyond the 0.8 m reach of the footprint.
  EXPECT_LE(metric(json, "unseen_reachable_area_m2"), 0.7) << json;
  EXPECT_GT(metric(json, "unreachable_area_m2"), 0.0) << json;
}

TEST(CoverageTool, KeepsTheWallDistanceOnTheLakeAndWarnsWhenAllowedLess) {
  // lake_30x30 by default: every piece keeps wall_distance (1 m, within 1 mm) and at least
  // 18 of its 20 turns are smoothed. The thesis's no-contact check passes an obstacle
  // within 0.1 m, and plan says so.
  const std::string lake = std::string(KC_SOURCE_DIR) + "/config/missions/lake_30x30.yaml";
  const std::string kept_dir = scratchDir() + "/lake_kept";
  const ToolRun kept = runTool("plan '" + lake + "' --out '" + kept_dir + "'");
  ASSERT_EQ(kept.exit_status, 0);
  const std::string kept_json = readText(kept_dir + "/metrics.json");
  EXPECT_GE(metric(kept_json, "min_obstacle_clearance_m"),
            1.0 - kinematic_coverage::core::kClearanceTolerance)
      << kept_json;
  EXPECT_GE(metric(kept_json, "turns_smoothed"), 18.0) << kept_json;
  EXPECT_TRUE(kept.err_lines.empty()) << kept.err_lines.front();

  const std::string thesis_dir = scratchDir() + "/lake_no_contact";
  const ToolRun thesis =
      runTool("plan '" + lake + "' --out '" + thesis_dir + "' --set smoothing_clearance=0");
  ASSERT_EQ(thesis.exit_status, 0);
  const double closest = metric(readText(thesis_dir + "/metrics.json"), "min_obstacle_clearance_m");
  EXPECT_LT(closest, 0.5);
  std::ostringstream expected;
  expected.precision(4);
  expected << "warning: the trajectory passes " << closest
           << " m from a wall or obstacle, nearer than wall_distance 1 m: smoothing_clearance 0 "
              "m lets its turns into the wall band (smoothing_clearance: wall_distance keeps "
              "them out)";
  EXPECT_NE(std::find(thesis.err_lines.begin(), thesis.err_lines.end(), expected.str()),
            thesis.err_lines.end())
      << expected.str();
}

/// Two squares, 20 m and 14 m, joined by a strait 1.2 m wide: with a 1 m wall distance the
/// offset free area falls into two parts, and the strait's clearance is 0.6 m.
std::string writeStraitMission(const std::string& goal = "[18, 18]") {
  const std::string path = scratchDir() + "/strait_goal_" + goal.substr(1, 2) + ".yaml";
  std::ofstream(path) << "polygon:\n  hull: [[0, 0], [20, 0], [20, 9.4], [22, 9.4], [22, 3], "
                         "[36, 3], [36, 17], [22, 17], [22, 10.6], [20, 10.6], [20, 20], "
                         "[0, 20]]\nstart: [2, 2]\ngoal: "
                      << goal
                      << "\nwall_distance: 1.0\n"
                         "sensor_distance: 1.0\nsmoothing: false\n";
  return path;
}

/// The number after `key` in `line`.
double numberAfter(const std::string& line, const std::string& key) {
  const std::size_t at = line.find(key);
  return at == std::string::npos ? std::nan("") : std::stod(line.substr(at + key.size()));
}

TEST(CoverageTool, DoesNotEnterAPartBeyondAGapNarrowerThanTheGapClearance) {
  const std::string mission = writeStraitMission();
  const std::string out_dir = scratchDir() + "/strait_out";
  const ToolRun run = runTool("plan '" + mission + "' --out '" + out_dir + "'");
  ASSERT_EQ(run.exit_status, 0) << (run.err_lines.empty() ? "" : run.err_lines[0]);
  ASSERT_EQ(run.err_lines.size(), 1u);
  const std::string& sealed = run.err_lines[0];
  EXPECT_NE(sealed.find("warning: the wall offset splits the free area: a part of 144 m^2 near"),
            std::string::npos)
      << sealed;
  EXPECT_NE(sealed.find("is not entered (it counts as unreachable): the widest gap to it, at ("),
            std::string::npos)
      << sealed;
  // The strait's clearance is 0.6 m, found to 0.1 % of the wall distance.
  EXPECT_NEAR(numberAfter(sealed, "), has "), 0.6, 0.001) << sealed;
  EXPECT_NE(sealed.find("m clearance, below gap_clearance 1 m"), std::string::npos) << sealed;
  const std::string json = readText(out_dir + "/metrics.json");
  EXPECT_GE(metric(json, "reachable_coverage_percent"), 99.9) << json;
  const double unreachable = metric(json, "unreachable_area_m2");
  EXPECT_GE(unreachable, 144.0) << json;
  EXPECT_GE(metric(json, "min_obstacle_clearance_m"), 1.0 - 1e-3) << json;
  // `evaluate` counts the room beyond the strait as unreachable too, as `plan` does.
  const std::string evaluated_dir = scratchDir() + "/strait_evaluated";
  const ToolRun evaluated = runTool("evaluate '" + mission + "' --trajectory '" + out_dir +
                                    "/trajectory.csv' --out '" + evaluated_dir + "'");
  ASSERT_EQ(evaluated.exit_status, 0)
      << (evaluated.err_lines.empty() ? "" : evaluated.err_lines[0]);
  const std::string evaluated_json = readText(evaluated_dir + "/metrics.json");
  EXPECT_NEAR(metric(evaluated_json, "unreachable_area_m2"), unreachable, 0.01) << evaluated_json;
  EXPECT_NEAR(metric(evaluated_json, "reachable_coverage_percent"),
              metric(json, "reachable_coverage_percent"), 0.01)
      << evaluated_json;

  // gap_clearance 0.5 m lets the transit through: the room is planned, and both the gap and
  // the trajectory's closest approach are warned of.
  const ToolRun allowed =
      runTool("plan '" + mission + "' --out '" + out_dir + "' --set gap_clearance=0.5");
  ASSERT_EQ(allowed.exit_status, 0) << (allowed.err_lines.empty() ? "" : allowed.err_lines[0]);
  ASSERT_EQ(allowed.err_lines.size(), 2u);
  EXPECT_NE(allowed.err_lines[0].find("warning: the wall offset splits the free area: transits to "
                                      "a part of 144 m^2 near"),
            std::string::npos)
      << allowed.err_lines[0];
  EXPECT_NEAR(numberAfter(allowed.err_lines[0], " with "), 0.6, 0.001) << allowed.err_lines[0];
  EXPECT_NE(allowed.err_lines[0].find("m clearance, nearer than wall_distance 1 m (gap_clearance "
                                      "0.5 m allows it)"),
            std::string::npos)
      << allowed.err_lines[0];
  EXPECT_NE(allowed.err_lines[1].find("gap_clearance 0.5 m lets its transits through narrower "
                                      "gaps"),
            std::string::npos)
      << allowed.err_lines[1];
  const std::string entered = readText(out_dir + "/metrics.json");
  EXPECT_GE(metric(entered, "reachable_coverage_percent"), 99.9) << entered;
  EXPECT_LE(metric(entered, "unreachable_area_m2"), unreachable - 144.0) << entered;
  // The transit runs in a corridor along the strait's middle (0.6 m), keeping the gap
  // clearance.
  EXPECT_GE(metric(entered, "min_obstacle_clearance_m"), 0.5 - 1e-3) << entered;
  EXPECT_LT(metric(entered, "min_obstacle_clearance_m"), 0.6) << entered;

  // A goal in the room beyond the strait cannot be reached keeping the gap clearance.
  expectInvalid("plan '" + writeStraitMission("[29, 10]") + "' --out '" + out_dir + "'",
                "goal (29, 10) lies in a part of 144 m^2 near");
  // A gap clearance outside (0, wall_distance] is refused, named.
  expectInvalid("plan '" + mission + "' --out '" + out_dir + "' --set gap_clearance=1.5",
                "--set gap_clearance=1.5: gap_clearance = 1.5 is out of range: it must be in (0, "
                "wall_distance = 1] (m), or the word wall_distance");
  expectInvalid("plan '" + mission + "' --out '" + out_dir + "' --set gap_clearance=0",
                "gap_clearance = 0 is out of range");

  // Only the largest part: the other one is named, and its area shows as unseen, in the
  // figures, in a warning that names where it is, and outlined in the plot.
  const ToolRun largest =
      runTool("plan '" + mission + "' --out '" + out_dir + "' --set offset_parts=largest");
  ASSERT_EQ(largest.exit_status, 0);
  ASSERT_EQ(largest.err_lines.size(), 2u);
  EXPECT_NE(largest.err_lines[0].find("is not planned (offset_parts: largest)"), std::string::npos)
      << largest.err_lines[0];
  EXPECT_NE(largest.err_lines[1].find("warning: the trajectory sees "), std::string::npos)
      << largest.err_lines[1];
  EXPECT_NE(largest.err_lines[1].find("% of the reachable area, less than 99.9 %"),
            std::string::npos)
      << largest.err_lines[1];
  // The unseen room: x 22 to 36, y 3 to 17, centred at (29, 10).
  double area = 0.0, x = 0.0, y = 0.0;
  const std::string& line = largest.err_lines[1];
  const std::size_t named = line.find("the largest unseen region ");
  ASSERT_NE(named, std::string::npos) << line;
  ASSERT_EQ(std::sscanf(line.c_str() + named, "the largest unseen region %lf m^2 around (%lf, %lf)",
                        &area, &x, &y),
            3)
      << line;
  EXPECT_GE(area, 144.0) << line;
  EXPECT_NEAR(x, 29.0, 1.0) << line;
  EXPECT_NEAR(y, 10.0, 1.0) << line;
  const std::string partial = readText(out_dir + "/metrics.json");
  EXPECT_LE(metric(partial, "reachable_coverage_percent"), 80.0) << partial;
  EXPECT_GE(metric(partial, "unseen_reachable_area_m2"), 144.0) << partial;
}

const std::string kLake75 = std::string(KC_SOURCE_DIR) + "/config/missions/lake_7_5.yaml";

/// `coverage_tool plan` of lake_7_5.yaml into the scratch directory `name` with `options`,
/// expecting success: the run and its metrics.json.
std::pair<ToolRun, std::string> planLake75(const std::string& name, const std::string& options) {
  const std::string out_dir = scratchDir() + "/" + name;
  std::filesystem::remove_all(out_dir);
  const ToolRun run = runTool("plan '" + kLake75 + "' --out '" + out_dir + "' " + options);
  EXPECT_EQ(run.exit_status, 0) << name;
  return {run, readText(out_dir + "/metrics.json")};
}

TEST(CoverageTool, WarnsWhenSmoothingLosesWhatTheUnsmoothedTrajectorySees) {
  // lake_7_5's footprint is 1.72 m wide and 0.21 m long: the reachable area reaches 0.11 m
  // beyond the 0.4 m wall distance, while the unsmoothed trajectory, along the walls between
  // lanes and turning in place, sees more of the wall band. The default smoothing keeps the
  // reachable area but not that: the loss is measured, at least the difference of the two
  // coverage losses (54.57 m^2 of free area), mostly beyond the reachable area, and warned of.
  const auto [smoothed_run, smoothed] = planLake75("smoothing_loss", "");
  const auto [sharp_run, sharp] = planLake75("smoothing_loss_sharp", "--set smoothing=false");
  constexpr double kFreeArea = 7.5 * 7.5 - 1.2 * 1.4;
  const double lost = metric(smoothed, "smoothing_lost_area_m2");
  EXPECT_GE(lost,
            (metric(smoothed, "coverage_loss_percent") - metric(sharp, "coverage_loss_percent")) /
                    100.0 * kFreeArea -
                0.01)
      << smoothed;
  EXPECT_GT(lost, 0.1) << smoothed;
  EXPECT_LT(metric(smoothed, "smoothing_lost_reachable_area_m2"), 0.1 * lost) << smoothed;
  ASSERT_EQ(smoothed_run.err_lines.size(), 1u);
  EXPECT_EQ(smoothed_run.err_lines[0].rfind("warning: smoothing loses ", 0), 0u)
      << smoothed_run.err_lines[0];
  EXPECT_TRUE(std::isnan(metric(sharp, "smoothing_lost_area_m2"))) << sharp;
  EXPECT_TRUE(sharp_run.err_lines.empty());

  // coverage_safe_area: free keeps the wall band too, still faster than unsmoothed.
  const auto [kept_run, kept] = planLake75("smoothing_loss_free", "--set coverage_safe_area=free");
  EXPECT_LT(metric(kept, "smoothing_lost_area_m2"), 0.1 / 100.0 * kFreeArea) << kept;
  EXPECT_LE(metric(kept, "coverage_loss_percent"), metric(sharp, "coverage_loss_percent") + 0.1)
      << kept;
  EXPECT_GT(metric(kept, "turns_smoothed"), 0.0) << kept;
  EXPECT_LT(metric(kept, "traversal_time_s"), metric(sharp, "traversal_time_s")) << kept;
  EXPECT_TRUE(kept_run.err_lines.empty()) << kept_run.err_lines.front();
}

TEST(CoverageTool, TheThesisPresetIsOneSwitchAway) {
  // --config config/thesis.yaml plans as the thesis did: Choset's cells, Algorithm 1's
  // smoothing and no coverage repair, the same as setting the three, and unlike the defaults.
  const auto traversal_time = [](const std::string& name, const std::string& options) {
    return metric(planLake75(name, options).second, "traversal_time_s");
  };
  const double thesis =
      traversal_time("thesis", "--config '" + std::string(KC_SOURCE_DIR) + "/config/thesis.yaml'");
  EXPECT_EQ(thesis,
            traversal_time("local",
                           "--set cell_joining=critical_points --set smoothing_strategy=local "
                           "--set coverage_repair=false --set boundary_simplification=0 "
                           "--set smoothing_clearance=0"));
  EXPECT_NE(thesis, traversal_time("default", ""));
  expectInvalid("plan '" + kLake75 + "' --out '" + scratchDir() + "/x' --config /nonexistent.yaml",
                "/nonexistent.yaml");
}

TEST(CoverageTool, ReportsEachCleaningStepAsAWarning) {
  const std::string path =
      writeMission("cleaning", mission("  hull: [[0, 0], [30, 0], [30, 0], [30, 30], [0, 30]]\n"
                                       "  holes:\n"
                                       "    - [[8, 8], [12, 8], [12, 12], [8, 12]]\n"
                                       "    - [[10, 10], [14, 10], [14, 14], [10, 14]]\n"
                                       "    - [[25, 15], [35, 15], [35, 20], [25, 20]]\n"));
  const std::string out_dir = scratchDir() + "/cleaning_out";
  const ToolRun run = runTool("plan '" + path + "' --out '" + out_dir + "'");
  ASSERT_EQ(run.exit_status, 0);
  std::vector<std::string> warnings;
  for (const std::string& line : run.err_lines) {
    if (line.rfind("warning: ", 0) == 0) warnings.push_back(line);
  }
  auto has = [&](const std::string& text) {
    return std::any_of(warnings.begin(), warnings.end(),
                       [&](const std::string& w) { return w.find(text) != std::string::npos; });
  };
  EXPECT_TRUE(has("warning: hull: 1 duplicate consecutive vertex dropped"));
  EXPECT_TRUE(has("warning: hole 0 and hole 1 overlap: merged"));
  EXPECT_TRUE(has("warning: hole 2 crosses the hull"));
}

TEST(CoverageTool, RejectsAnEmptyOffsetFreeArea) {
  expectInvalidMission(mission(kSquare, "wall_distance: 20\n"), "the offset free area is empty");
}

TEST(CoverageTool, RejectsAPlanOverThePlanningLimits) {
  // The planner's size limits: a 2 km square under a 1 cm footprint needs 666 000 sweep lanes.
  expectInvalidMission(mission("  hull: [[0, 0], [2000, 0], [2000, 2000], [0, 2000]]\n",
                               "sensor_model: line\nlateral_footprint: 0.01\n"),
                       "the cells need at least 666000 sweep lanes, 646000 more than the limit "
                       "of 20000");
}

TEST(CoverageTool, RefusesAMapOverMaxMemoryBeforeAllocatingIt) {
  // A comb of 2 400 teeth, 3 m wide and 3 m apart: 2 401 cells, 9 606 generalized TSP nodes,
  // about 900 MB by the estimate (its transitions routed between nearby cells, its dense
  // matrix 740 MB). Under a 512 MiB address-space limit its plan fails to allocate (measured:
  // std::bad_alloc after the sweeps); the estimate refuses the map first, with exit 2 and
  // the figures behind it.
  constexpr int kTeeth = 2400;
  const double width = 6.0 * kTeeth - 3.0;
  std::ostringstream hull;
  hull << "  hull: [[0, 0], [" << width << ", 0]";
  for (int i = kTeeth - 1; i >= 0; --i) {
    const double left = 6.0 * i;
    if (i < kTeeth - 1) hull << ", [" << left + 3.0 << ", 10]";
    hull << ", [" << left + 3.0 << ", 20], [" << left << ", 20]";
    if (i > 0) hull << ", [" << left << ", 10]";
  }
  hull << "]\n";
  const std::string path =
      writeMission("comb", mission(hull.str(), "wall_distance: 0\ncell_joining: critical_points\n",
                                   "[1, 1]", "[" + std::to_string(width - 1.0) + ", 1]"));
  const std::string out_dir = scratchDir() + "/comb_out";
  std::filesystem::remove_all(out_dir);
  const std::string err = scratchDir() + "/comb_stderr.txt";
  const std::string command = "(ulimit -v 524288; '" + std::string(KC_TOOL_PATH) + "' plan '" +
                              path + "' --out '" + out_dir +
                              "' --set max_memory_mb=300) >/dev/null 2>'" + err + "'";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  const std::vector<std::string> err_lines = lines(readText(err));
  ASSERT_EQ(err_lines.size(), 1u);
  EXPECT_NE(err_lines[0].find("error: the plan would need about "), std::string::npos)
      << err_lines[0];
  EXPECT_NE(err_lines[0].find("MB, more than max_memory_mb 300 MB (2401 cells with "),
            std::string::npos)
      << err_lines[0];
  EXPECT_FALSE(std::filesystem::exists(out_dir + "/waypoints.csv"));
}

std::string writeTrajectory(const std::string& name, const std::string& csv) {
  const std::string path = scratchDir() + "/" + name + ".csv";
  std::ofstream(path) << csv;
  return path;
}

const char* const kCoverageKeys[] = {"coverage_percent", "coverage_loss_percent",
                                     "reachable_coverage_percent", "unseen_reachable_area_m2",
                                     "unreachable_area_m2"};

TEST(CoverageTool, EvaluatesPlansOwnTrajectoryToPlansFigures) {
  const std::string lake = std::string(KC_SOURCE_DIR) + "/config/missions/lake_30x30.yaml";
  const std::string plan_dir = scratchDir() + "/evaluate_plan_out";
  const std::string evaluate_dir = scratchDir() + "/evaluate_out";
  std::filesystem::remove_all(plan_dir);
  std::filesystem::remove_all(evaluate_dir);
  ASSERT_EQ(runTool("plan '" + lake + "' --out '" + plan_dir + "'").exit_status, 0);
  const ToolRun run = runTool("evaluate '" + lake + "' --trajectory '" + plan_dir +
                              "/trajectory.csv' --out '" + evaluate_dir + "'");
  ASSERT_EQ(run.exit_status, 0) << (run.err_lines.empty() ? "" : run.err_lines[0]);
  const std::vector<std::string> out_lines = lines(run.out);
  ASSERT_FALSE(out_lines.empty());
  EXPECT_EQ(out_lines.back(),
            "wrote " + evaluate_dir + "/metrics.json " + evaluate_dir + "/plot.png");
  EXPECT_EQ(readText(evaluate_dir + "/plot.png").substr(0, 8), "\x89PNG\r\n\x1a\n");
  for (const std::string stage :
       {"load: ", "read: ", "validate: ", "clean: ", "offset: ", "coverage: "}) {
    EXPECT_TRUE(std::any_of(out_lines.begin(), out_lines.end(), [&](const std::string& line) {
      return line.rfind(stage, 0) == 0;
    })) << stage;
  }
  EXPECT_TRUE(run.err_lines.empty()) << run.err_lines.front();

  const std::string planned = readText(plan_dir + "/metrics.json");
  const std::string evaluated = readText(evaluate_dir + "/metrics.json");
  for (const char* key : kCoverageKeys) {
    EXPECT_GE(metric(evaluated, key), 0.0) << key << " in " << evaluated;
    if (std::string(key).find("percent") != std::string::npos) {
      EXPECT_LE(metric(evaluated, key), 100.0) << key << " in " << evaluated;
    }
    // The same poses on the same raster: the same figures.
    EXPECT_EQ(metric(evaluated, key), metric(planned, key)) << key;
  }
  const std::size_t rows = lines(readText(plan_dir + "/trajectory.csv")).size() - 1;
  EXPECT_EQ(metric(evaluated, "pose_count"), static_cast<double>(rows));
  // The polyline through the poses: the planned length, arcs replaced by short chords.
  EXPECT_LE(metric(evaluated, "trajectory_length_m"), metric(planned, "trajectory_length_m"));
  EXPECT_NEAR(metric(evaluated, "trajectory_length_m"), metric(planned, "trajectory_length_m"),
              1e-3 * metric(planned, "trajectory_length_m"));
  EXPECT_GT(metric(evaluated, "evaluation_time_s"), 0.0);
}

TEST(CoverageTool, EvaluatesAThinnedTrajectoryFileToPlansFiguresWithinATenthOfAPoint) {
  // trajectory_output_spacing thins the files only: metrics.json keeps every pose's
  // figures, and evaluate on the thinned file agrees with them within 0.1 point, on the
  // lake and on the shipped lake chart (smoothed, default sampling).
  const std::string missions = std::string(KC_SOURCE_DIR) + "/config/missions/";
  for (const char* mission : {"lake_30x30.yaml", "kleinhesseloher_see.geojson"}) {
    SCOPED_TRACE(mission);
    const std::string dir = scratchDir() + "/thinned_" + mission;
    std::filesystem::remove_all(dir);
    const std::string path = missions + mission;
    ASSERT_EQ(runTool("plan '" + path + "' --out '" + dir + "/full'").exit_status, 0);
    const ToolRun run = runTool("plan '" + path + "' --out '" + dir +
                                "/thinned' --set trajectory_output_spacing=5");
    ASSERT_EQ(run.exit_status, 0) << run.out;
    EXPECT_NE(run.out.find("thin: the trajectory files hold "), std::string::npos) << run.out;
    const std::size_t full_rows = lines(readText(dir + "/full/trajectory.csv")).size();
    const std::size_t thinned_rows = lines(readText(dir + "/thinned/trajectory.csv")).size();
    EXPECT_LT(thinned_rows, full_rows / 2);
    const std::string full = readText(dir + "/full/metrics.json");
    const std::string planned = readText(dir + "/thinned/metrics.json");
    EXPECT_EQ(metric(planned, "coverage_percent"), metric(full, "coverage_percent"));
    const ToolRun evaluate = runTool("evaluate '" + path + "' --trajectory '" + dir +
                                     "/thinned/trajectory.csv' --out '" + dir + "/evaluated'");
    ASSERT_EQ(evaluate.exit_status, 0) << evaluate.out;
    const std::string evaluated = readText(dir + "/evaluated/metrics.json");
    EXPECT_EQ(metric(evaluated, "pose_count"), static_cast<double>(thinned_rows - 1));
    for (const char* key : {"coverage_percent", "reachable_coverage_percent"}) {
      EXPECT_NEAR(metric(evaluated, key), metric(planned, key), 0.1) << key;
    }
    EXPECT_NEAR(metric(evaluated, "trajectory_length_m"), metric(planned, "trajectory_length_m"),
                1e-3 * metric(planned, "trajectory_length_m"));
  }
}

TEST(CoverageTool, EvaluatesAStraightSweepAsItsAnalyticArea) {
  // 30 m square, default frustum sensor: W = 6 tan(1.135), L = 6 tan(0.26). A straight
  // run from x = 5 to x = 25 along y = 15, with the columns in another order and an extra
  // one, sees a W x (20 + L) rectangle.
  const std::string path = writeMission("evaluate_square", mission(kSquare));
  const std::string trajectory =
      writeTrajectory("sweep", "yaw, note ,y,x\n0,a,15,5\n0,b,15,10.25\n0,c,15,17.5\n0,d,15,25\n");
  const std::string out_dir = scratchDir() + "/evaluate_sweep_out";
  const ToolRun run =
      runTool("evaluate '" + path + "' --trajectory '" + trajectory + "' --out '" + out_dir + "'");
  ASSERT_EQ(run.exit_status, 0) << (run.err_lines.empty() ? "" : run.err_lines[0]);
  const std::string json = readText(out_dir + "/metrics.json");
  const double width = 6.0 * std::tan(2.27 / 2.0);
  const double length = 6.0 * std::tan(0.52 / 2.0);
  const double expected = 100.0 * width * (20.0 + length) / 900.0;
  EXPECT_NEAR(metric(json, "coverage_percent"), expected, 0.1) << json;
  EXPECT_NEAR(metric(json, "coverage_loss_percent"), 100.0 - expected, 0.1) << json;
  EXPECT_EQ(metric(json, "pose_count"), 4.0);
  EXPECT_DOUBLE_EQ(metric(json, "trajectory_length_m"), 20.0);
  // --set reaches the sensor: a narrower footprint sees less.
  const ToolRun narrow = runTool("evaluate '" + path + "' --trajectory '" + trajectory +
                                 "' --out '" + out_dir + "' --set lateral_fov=1.2");
  ASSERT_EQ(narrow.exit_status, 0);
  const double narrow_expected = 100.0 * 6.0 * std::tan(0.6) * (20.0 + length) / 900.0;
  EXPECT_NEAR(metric(readText(out_dir + "/metrics.json"), "coverage_percent"), narrow_expected,
              0.1);
}

TEST(CoverageTool, EvaluateRejectsBadInputWithOneLine) {
  const std::string path = writeMission("evaluate_ok", mission(kSquareWithHole));
  const std::string good = writeTrajectory("good", "x,y,yaw\n5,5,0\n9,5,0\n");
  const std::string out_dir = scratchDir() + "/evaluate_invalid_out";
  std::filesystem::remove_all(out_dir);
  const auto evaluate = [&](const std::string& trajectory, const std::string& expected) {
    expectInvalid(
        "evaluate '" + path + "' --trajectory '" + trajectory + "' --out '" + out_dir + "'",
        expected);
    EXPECT_FALSE(std::filesystem::exists(out_dir + "/metrics.json"));
  };
  evaluate(scratchDir() + "/missing.csv", "missing.csv: no such file");
  evaluate(writeTrajectory("bad_row", "x,y,yaw\n5,5,0\n6,abc,0\n"),
           "bad_row.csv:3: column y: 'abc' is not a number");
  evaluate(writeTrajectory("short_row", "x,y,yaw\n5,5,0\n\n6,5\n"),
           "short_row.csv:4: 2 fields, but the header has 3");
  evaluate(writeTrajectory("nan", "x,y,yaw\n5,5,0\n6,5,nan\n"),
           "nan.csv:3: column yaw: 'nan' is not finite");
  evaluate(writeTrajectory("empty", "x,y,yaw\n"), "empty.csv: the file has no rows");
  evaluate(writeTrajectory("no_yaw", "x,y,t\n5,5,0\n"), "no_yaw.csv:1: the header has no 'yaw'");
  evaluate(writeTrajectory("bad_kind", "t,x,y,yaw,kind\n0,5,5,0,segment\n1,6,5,0,\n"),
           "bad_kind.csv:3: column kind: '' is not a kind name (segment, arc, rotation, "
           "clothoid, ...: lower-case letters, digits and underscores)");
  evaluate(writeTrajectory("time", "t,x,y,yaw\n1,5,5,0\n0.5,6,5,0\n"),
           "time.csv:3: column t: 0.5 is before the previous row's time");
  expectInvalid("evaluate '" + path + "' --out '" + out_dir + "'",
                "--trajectory FILE.csv is required");
  expectInvalid("evaluate '" + path + "' --trajectory '" + good + "'", "--out DIR is required");
  expectInvalid("evaluate '" + path + "' --trajectory", "--trajectory needs a value");
  expectInvalid("evaluate --trajectory '" + good + "' --out x", "no mission file given");
  expectInvalid("evaluate '" + path + "' --trajectory '" + good + "' --out x --waypoints y",
                "unknown option '--waypoints'");
  // The mission is validated and cleaned as plan does it.
  const std::string crossed =
      writeMission("evaluate_crossed", mission("  hull: [[0, 0], [30, 30], [30, 0], [0, 30]]\n"));
  expectInvalid("evaluate '" + crossed + "' --trajectory '" + good + "' --out '" + out_dir + "'",
                "hull is self-intersecting");
  const std::string walled =
      writeMission("evaluate_walled", mission(kSquare, "wall_distance: 20\n"));
  expectInvalid("evaluate '" + walled + "' --trajectory '" + good + "' --out '" + out_dir + "'",
                "the offset free area is empty");
  EXPECT_FALSE(std::filesystem::exists(out_dir + "/metrics.json"));
  const ToolRun help = runTool("evaluate --help");
  EXPECT_EQ(help.exit_status, 0);
  EXPECT_NE(help.out.find("--trajectory FILE.csv"), std::string::npos);
}

/// The keys of a one-line JSON object and of its nested objects, in order.
std::vector<std::string> jsonKeys(const std::string& json) {
  std::vector<std::string> keys;
  for (std::size_t at = json.find('"'); at != std::string::npos; at = json.find('"', at)) {
    const std::size_t end = json.find('"', at + 1);
    keys.push_back(json.substr(at + 1, end - at - 1));
    at = end + 1;
  }
  return keys;
}

/// The robot model follows plan's trajectory; simulate writes actual.csv, the
/// metrics.json keys of docs/REFERENCE.md, Metrics, and plot.png.
TEST(CoverageTool, SimulatesPlansTrajectoryAndWritesItsFiles) {
  const std::string lake = std::string(KC_SOURCE_DIR) + "/config/missions/lake_30x30.yaml";
  const std::string plan_dir = scratchDir() + "/simulate_plan_out";
  const std::string out_dir = scratchDir() + "/simulate_out";
  std::filesystem::remove_all(plan_dir);
  std::filesystem::remove_all(out_dir);
  ASSERT_EQ(runTool("plan '" + lake + "' --out '" + plan_dir + "'").exit_status, 0);
  const std::string trajectory = plan_dir + "/trajectory.csv";
  const ToolRun run =
      runTool("simulate '" + lake + "' --trajectory '" + trajectory + "' --out '" + out_dir + "'");
  ASSERT_EQ(run.exit_status, 0) << (run.err_lines.empty() ? "" : run.err_lines[0]);
  EXPECT_TRUE(run.err_lines.empty()) << run.err_lines.front();
  const std::vector<std::string> out_lines = lines(run.out);
  ASSERT_FALSE(out_lines.empty());
  EXPECT_EQ(out_lines.back(), "wrote " + out_dir + "/actual.csv " + out_dir + "/metrics.json " +
                                  out_dir + "/plot.png " + out_dir + "/poses.png " + out_dir +
                                  "/errors.png");
  for (const char* figure : {"/plot.png", "/poses.png", "/errors.png"}) {
    EXPECT_EQ(readText(out_dir + figure).substr(0, 8), "\x89PNG\r\n\x1a\n") << figure;
  }

  const std::string json = readText(out_dir + "/metrics.json");
  const std::vector<std::string> percentiles{"1", "5", "10", "25", "50", "75", "90", "95", "99"};
  std::vector<std::string> keys{"traversal_time_s", "tracking_error_sum_m", "tracking_error_mean_m",
                                "tracking_error_percentiles_m"};
  keys.insert(keys.end(), percentiles.begin(), percentiles.end());
  for (const char* key :
       {"tracking_error_x_mean_m", "tracking_error_y_mean_m", "tracking_error_x_max_m",
        "tracking_error_y_max_m", "tracking_error_target_sum_m", "tracking_error_target_mean_m",
        "tracking_error_target_percentiles_m"}) {
    keys.push_back(key);
  }
  keys.insert(keys.end(), percentiles.begin(), percentiles.end());
  // The default controller, timed, tracks a reference: its time-matched error.
  keys.push_back("tracking_error_time_matched_sum_m");
  keys.push_back("tracking_error_time_matched_mean_m");
  keys.push_back("tracking_error_time_matched_percentiles_m");
  keys.insert(keys.end(), percentiles.begin(), percentiles.end());
  for (const char* key :
       {"reference_excess_time_s", "tracking_error_2hz_sum_m", "tracking_error_2hz_mean_m",
        "tracking_error_target_2hz_sum_m", "tracking_error_target_2hz_mean_m",
        "tracking_error_time_matched_2hz_sum_m", "tracking_error_time_matched_2hz_mean_m"}) {
    keys.push_back(key);
  }
  for (const char* key :
       {"driven_min_clearance_m", "driven_obstacle_time_s", "driven_outside_hull_time_s"}) {
    keys.push_back(key);
  }
  for (const char* key : {"coverage_percent", "coverage_loss_percent", "reachable_coverage_percent",
                          "unseen_reachable_area_m2", "unreachable_area_m2"}) {
    keys.push_back(key);
  }
  EXPECT_EQ(jsonKeys(json), keys) << json;
  // The axis parts of an error are at most the error; the target piece is never nearer
  // than the nearest point of the whole path.
  EXPECT_LE(metric(json, "tracking_error_x_mean_m"), metric(json, "tracking_error_mean_m"));
  EXPECT_LE(metric(json, "tracking_error_y_mean_m"), metric(json, "tracking_error_mean_m"));
  EXPECT_GE(metric(json, "tracking_error_target_sum_m"), metric(json, "tracking_error_sum_m"));
  EXPECT_GT(metric(json, "reachable_coverage_percent"), 99.0);
  // The driven path keeps off the walls and obstacles (the smoothed arcs may enter the wall
  // band: the planned trajectory comes within 0.1 m of an obstacle here).
  EXPECT_GT(metric(json, "driven_min_clearance_m"), 0.0);
  EXPECT_EQ(metric(json, "driven_obstacle_time_s"), 0.0);
  EXPECT_EQ(metric(json, "driven_outside_hull_time_s"), 0.0);
  double previous = 0.0;
  for (const char* percentile : {"1", "5", "10", "25", "50", "75", "90", "95", "99"}) {
    const double value = metric(json, percentile);
    EXPECT_GE(value, previous) << percentile;
    previous = value;
  }
  EXPECT_LE(metric(json, "tracking_error_mean_m"), metric(json, "99"));
  EXPECT_NEAR(metric(json, "coverage_percent") + metric(json, "coverage_loss_percent"), 100.0,
              1e-9);
  EXPECT_GT(metric(json, "coverage_percent"), 99.0);

  // actual.csv: a row per step from the trajectory's first pose at t = 0 to the last at
  // traversal_time_s, sim_dt apart; the error sum is the mean times the steps.
  const std::vector<std::string> actual = lines(readText(out_dir + "/actual.csv"));
  ASSERT_GT(actual.size(), 100u);
  EXPECT_EQ(actual[0], "t,x,y,yaw,error_m,error_x_m,error_y_m,target_error_m");
  const std::vector<std::string> desired = lines(readText(trajectory));
  const std::string first_pose = desired[1].substr(0, desired[1].rfind(','));
  EXPECT_EQ(actual[1], first_pose + ",0,0,0,0");
  const double last_t = std::stod(actual.back().substr(0, actual.back().find(',')));
  EXPECT_DOUBLE_EQ(last_t, metric(json, "traversal_time_s"));
  EXPECT_NEAR(last_t, 0.1 * static_cast<double>(actual.size() - 2), 1e-6);
  EXPECT_NEAR(metric(json, "tracking_error_sum_m"),
              metric(json, "tracking_error_mean_m") * static_cast<double>(actual.size() - 2),
              1e-6 * metric(json, "tracking_error_sum_m"));

  // --set reaches the robot: a current that the controller does not know of makes it track
  // worse.
  const ToolRun drift = runTool("simulate '" + lake + "' --trajectory '" + trajectory +
                                "' --out '" + out_dir + "' --set current_sigma=0.05");
  ASSERT_EQ(drift.exit_status, 0);
  EXPECT_GT(metric(readText(out_dir + "/metrics.json"), "tracking_error_mean_m"),
            5.0 * metric(json, "tracking_error_mean_m"));
}

TEST(CoverageTool, SimulateRepeatsExactlyForTheSameSeed) {
  // The lake's disturbances are seeded (disturbance_seed): two runs give identical files,
  // and another seed another run.
  const std::string lake = std::string(KC_SOURCE_DIR) + "/config/missions/lake_7_5.yaml";
  const std::string plan_dir = scratchDir() + "/repeat_plan_out";
  std::filesystem::remove_all(plan_dir);
  ASSERT_EQ(runTool("plan '" + lake + "' --out '" + plan_dir + "'").exit_status, 0);
  const auto simulate = [&](const std::string& name, const std::string& seed) {
    const std::string out_dir = scratchDir() + "/" + name;
    std::filesystem::remove_all(out_dir);
    const ToolRun run = runTool("simulate '" + lake + "' --trajectory '" + plan_dir +
                                "/trajectory.csv' --out '" + out_dir +
                                "' --set current_sigma=0.02 --set navigation_sigma=0.1 "
                                "--set disturbance_seed=" +
                                seed);
    EXPECT_EQ(run.exit_status, 0) << name;
    return readText(out_dir + "/actual.csv");
  };
  const std::string first = simulate("repeat_a", "1");
  EXPECT_GT(first.size(), 1000u);
  EXPECT_EQ(simulate("repeat_b", "1"), first);
  EXPECT_NE(simulate("repeat_c", "2"), first);
}

TEST(CoverageTool, SimulateWarnsLoudlyWhenTheRobotHitsAnObstacle) {
  // A trajectory straight through the obstacle (8..12, 8..12): the run is valid, but the
  // contact is the first thing the output says about it.
  const std::string path = writeMission("simulate_contact", mission(kSquareWithHole));
  const std::string through =
      writeTrajectory("simulate_through", "t,x,y,yaw\n0,5,10,0\n20,15,10,0\n");
  const std::string out_dir = scratchDir() + "/simulate_contact_out";
  std::filesystem::remove_all(out_dir);
  const ToolRun run =
      runTool("simulate '" + path + "' --trajectory '" + through + "' --out '" + out_dir + "'");
  ASSERT_EQ(run.exit_status, 0);
  ASSERT_EQ(run.err_lines.size(), 1u);
  EXPECT_EQ(run.err_lines[0].rfind("warning: the robot drove into an obstacle or out through the "
                                   "hull, first at t = ",
                                   0),
            0u)
      << run.err_lines[0];
  EXPECT_NE(run.out.find("clearance: CONTACT: the driven path entered an obstacle"),
            std::string::npos)
      << run.out;
  const std::string json = readText(out_dir + "/metrics.json");
  EXPECT_EQ(metric(json, "driven_min_clearance_m"), 0.0);
  // 4 m of obstacle at v_max = 0.5 m/s.
  EXPECT_GE(metric(json, "driven_obstacle_time_s"), 7.5);

  // A navigation error larger than the position tolerance: the robot will hunt.
  const std::string beside = writeTrajectory("simulate_beside", "t,x,y,yaw\n0,5,4,0\n20,15,4,0\n");
  const ToolRun noisy = runTool("simulate '" + path + "' --trajectory '" + beside + "' --out '" +
                                out_dir + "' --set navigation_sigma=0.1");
  ASSERT_EQ(noisy.exit_status, 0);
  ASSERT_EQ(noisy.err_lines.size(), 1u);
  EXPECT_EQ(
      noisy.err_lines[0].rfind(
          "warning: position_tolerance = 0.05 m is less than 3 x navigation_sigma = 0.3 m", 0),
      0u)
      << noisy.err_lines[0];
}

TEST(CoverageTool, SimulateRejectsBadInputWithOneLine) {
  const std::string path = writeMission("simulate_ok", mission(kSquareWithHole));
  const std::string good = writeTrajectory("simulate_good", "t,x,y,yaw\n0,5,5,0\n8,9,5,0\n");
  const std::string out_dir = scratchDir() + "/simulate_invalid_out";
  std::filesystem::remove_all(out_dir);
  const auto simulate = [&](const std::string& trajectory, const std::string& options,
                            const std::string& expected) {
    expectInvalid("simulate '" + path + "' --trajectory '" + trajectory + "' --out '" + out_dir +
                      "' " + options,
                  expected);
    EXPECT_FALSE(std::filesystem::exists(out_dir + "/actual.csv"));
    EXPECT_FALSE(std::filesystem::exists(out_dir + "/metrics.json"));
  };
  simulate(scratchDir() + "/missing.csv", "", "missing.csv: no such file");
  simulate(writeTrajectory("simulate_bad_row", "x,y,yaw\n5,5,0\n6,abc,0\n"), "",
           "simulate_bad_row.csv:3: column y: 'abc' is not a number");
  simulate(writeTrajectory("simulate_empty", "x,y,yaw\n"), "",
           "simulate_empty.csv: the file has no rows");
  simulate(good, "--set sim_dt=0", "sim_dt = 0 is out of range: it must be a finite number > 0");
  simulate(good, "--set yaw_gain=20",
           "--set yaw_gain=20: yaw_gain = 20 is out of range: it must be a finite number > 0 "
           "(1/s), and yaw_gain * sim_dt <= 1 (sim_dt = 0.1)");
  simulate(good, "--set current_x=.nan", "current_x: the value '.nan' is not finite");
  simulate(good, "--set pose_rate=0",
           "--set pose_rate=0: pose_rate = 0 is out of range: it must be a finite number > 0 (Hz)");
  simulate(good, "--set los_lookahead=-1",
           "--set los_lookahead=-1: los_lookahead = -1 is out of range: it must be a finite "
           "number >= 0 (m)");
  simulate(good, "--set controller=pid",
           "--set controller=pid: controller = 'pid' is not one of: los, pose_stream, setpoint, "
           "timed");
  simulate(good, "--set sim_time_limit=1e9",
           "sim_time_limit = 1000000000 is out of range: it must be a finite number > 0 (s), and "
           "sim_time_limit / sim_dt <= 5000000 (sim_dt = 0.1)");
  // An impossible request: a current faster than the robot, against its way (the setpoint
  // follower, whose commands v_max bounds).
  simulate(good, "--set controller=setpoint --set current_x=-1 --set sim_time_limit=60",
           "did not reach the last pose within sim_time_limit = 60 s (it was driving to pose 2 "
           "of 2)");
  expectInvalid("simulate '" + path + "' --out '" + out_dir + "'",
                "--trajectory FILE.csv is required");
  expectInvalid("simulate '" + path + "' --trajectory '" + good + "'", "--out DIR is required");
  expectInvalid("simulate '" + path + "' --trajectory '" + good + "' --out x --visited y",
                "unknown option '--visited'");
  const std::string walled =
      writeMission("simulate_walled", mission(kSquare, "wall_distance: 20\n"));
  expectInvalid("simulate '" + walled + "' --trajectory '" + good + "' --out '" + out_dir + "'",
                "the offset free area is empty");
  EXPECT_FALSE(std::filesystem::exists(out_dir));
  const ToolRun help = runTool("simulate --help");
  EXPECT_EQ(help.exit_status, 0);
  EXPECT_NE(help.out.find("--trajectory FILE.csv"), std::string::npos);
}

/// Replanning end to end: the lake mission followed for 40 % of its trajectory, then both
/// obstacles moved by 2 m; `replan` writes the files of plan and remaining.yaml, starts at
/// the last visited pose and, with the visited poses, sees nearly all of the free area.
TEST(CoverageTool, ReplansTheLakeDriftScenario) {
  const std::string lake = std::string(KC_SOURCE_DIR) + "/config/missions/lake_30x30.yaml";
  const std::string plan_dir = scratchDir() + "/replan_plan";
  const std::string out_dir = scratchDir() + "/replan_out";
  std::filesystem::remove_all(out_dir);
  ASSERT_EQ(runTool("plan '" + lake + "' --out '" + plan_dir + "'").exit_status, 0);
  const std::vector<std::string> trajectory = lines(readText(plan_dir + "/trajectory.csv"));
  const std::string visited = scratchDir() + "/visited.csv";
  {
    std::ofstream file(visited);
    for (std::size_t i = 0; i < trajectory.size() * 4 / 10; ++i) file << trajectory[i] << "\n";
  }
  const std::string updated =
      writeMission("updated",
                   "polygon:\n  hull: [[0, 0], [30, 0], [30, 30], [0, 30]]\n  holes:\n"
                   "    - [[9, 10], [14, 10], [14, 16], [9, 16]]\n"
                   "    - [[20, 18], [25, 19], [26, 24], [21, 26], [18, 22]]\n");
  const ToolRun run = runTool("replan '" + lake + "' --updated '" + updated + "' --visited '" +
                              visited + "' --out '" + out_dir + "'");
  ASSERT_EQ(run.exit_status, 0) << (run.err_lines.empty() ? run.out : run.err_lines[0]);
  for (const char* file :
       {"waypoints.csv", "trajectory.csv", "metrics.json", "plot.png", "remaining.yaml"}) {
    EXPECT_TRUE(std::filesystem::exists(out_dir + "/" + file)) << file;
  }
  const std::string metrics = readText(out_dir + "/metrics.json");
  EXPECT_GE(metric(metrics, "combined_coverage_percent"), 99.0);
  EXPECT_GT(metric(metrics, "min_obstacle_clearance_m"), 0.0);
  // The new path starts where the robot stopped.
  const std::vector<std::string> last_visited = lines(readText(visited));
  const std::vector<std::string> waypoints = lines(readText(out_dir + "/waypoints.csv"));
  ASSERT_GE(waypoints.size(), 3u);
  std::istringstream last_row(last_visited.back());
  std::istringstream first_row(waypoints[1]);
  double t = 0, x = 0, y = 0, wx = 0, wy = 0;
  char comma = 0;
  last_row >> t >> comma >> x >> comma >> y;
  first_row >> wx >> comma >> wy;
  EXPECT_NEAR(wx, x, 1e-6);
  EXPECT_NEAR(wy, y, 1e-6);
  EXPECT_EQ(readText(out_dir + "/remaining.yaml").rfind("- hull: [[", 0), 0u);

  // Invalid input: one line, exit 2.
  expectInvalid("replan '" + lake + "' --updated '" + updated + "' --out '" + out_dir + "'",
                "--visited");
  const std::string empty = scratchDir() + "/empty_visited.csv";
  std::ofstream(empty) << "x,y,yaw\n";
  expectInvalid("replan '" + lake + "' --updated '" + updated + "' --visited '" + empty +
                    "' --out '" + out_dir + "'",
                "");
}

/// The x and y columns of a waypoints.csv (header "x,y,yaw").
std::vector<std::pair<double, double>> waypointRows(const std::string& path) {
  std::vector<std::pair<double, double>> rows;
  const std::vector<std::string> text = lines(readText(path));
  for (std::size_t i = 1; i < text.size(); ++i) {
    double x = 0.0, y = 0.0;
    if (std::sscanf(text[i].c_str(), "%lf,%lf", &x, &y) == 2) rows.emplace_back(x, y);
  }
  return rows;
}

TEST(CoverageTool, GeoJsonMissionsPlanAsTheirMetreMissions) {
  const std::string lake = std::string(KC_SOURCE_DIR) + "/config/missions/lake_30x30.yaml";
  const std::string dir = scratchDir() + "/geojson";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const kinematic_coverage::core::GeoPoint datum{47.3769, 8.5417};
  ToolRun run =
      runTool("export '" + lake + "' --datum 47.3769,8.5417 --out '" + dir + "/lake.geojson'");
  ASSERT_EQ(run.exit_status, 0) << run.out;
  run = runTool("plan '" + lake + "' --out '" + dir + "/metres'");
  ASSERT_EQ(run.exit_status, 0) << run.out;
  run = runTool("plan '" + dir + "/lake.geojson' --out '" + dir + "/geo'");
  ASSERT_EQ(run.exit_status, 0) << run.out;
  EXPECT_NE(run.out.find("at datum (47.3769, 8.5417)"), std::string::npos) << run.out;

  // The same plan: time cost to 1e-6 relative, waypoints to 1e-6 m.
  const std::string metres_json = readText(dir + "/metres/metrics.json");
  const std::string geo_json = readText(dir + "/geo/metrics.json");
  EXPECT_NEAR(metric(geo_json, "time_cost_s") / metric(metres_json, "time_cost_s"), 1.0, 1e-6);
  EXPECT_NE(geo_json.find("\"datum\": [47.3769, 8.5417]"), std::string::npos) << geo_json;
  EXPECT_NE(geo_json.find("\"frame_id\": \"map\""), std::string::npos) << geo_json;
  const auto metres = waypointRows(dir + "/metres/waypoints.csv");
  const auto geo = waypointRows(dir + "/geo/waypoints.csv");
  ASSERT_EQ(geo.size(), metres.size());
  ASSERT_GT(geo.size(), 2u);
  for (std::size_t i = 0; i < geo.size(); ++i) {
    EXPECT_NEAR(geo[i].first, metres[i].first, 1e-6) << "waypoint " << i;
    EXPECT_NEAR(geo[i].second, metres[i].second, 1e-6) << "waypoint " << i;
  }

  // waypoints.geojson: a FeatureCollection of one LineString whose positions (to 1e-7
  // degrees, at most 6 mm off) project back onto the waypoints within 1 cm, with a time
  // per position.
  const YAML::Node root = YAML::LoadFile(dir + "/geo/waypoints.geojson");
  ASSERT_EQ(root["type"].as<std::string>(), "FeatureCollection");
  const YAML::Node feature = root["features"][0];
  ASSERT_EQ(feature["geometry"]["type"].as<std::string>(), "LineString");
  const YAML::Node coordinates = feature["geometry"]["coordinates"];
  ASSERT_EQ(coordinates.size(), geo.size());
  ASSERT_EQ(feature["properties"]["times"].size(), geo.size());
  // The frame it was planned in, as metrics.json names it.
  EXPECT_EQ(feature["properties"]["frame_id"].as<std::string>(), "map");
  EXPECT_EQ(feature["properties"]["projection"].as<std::string>(), "local");
  EXPECT_EQ(feature["properties"]["datum"][0].as<double>(), 47.3769);
  EXPECT_EQ(feature["properties"]["datum"][1].as<double>(), 8.5417);
  EXPECT_NE(geo_json.find("\"projection\": \"local\""), std::string::npos) << geo_json;
  const kinematic_coverage::core::MissionFrame frame(
      datum, kinematic_coverage::core::MapProjection::kLocal);
  for (std::size_t i = 0; i < geo.size(); ++i) {
    const kinematic_coverage::core::Point2 local =
        frame.toLocal({coordinates[i][1].as<double>(), coordinates[i][0].as<double>()}, "waypoint");
    EXPECT_NEAR(local.x(), geo[i].first, 1e-2) << "waypoint " << i;
    EXPECT_NEAR(local.y(), geo[i].second, 1e-2) << "waypoint " << i;
  }
  const YAML::Node trajectory = YAML::LoadFile(dir + "/geo/trajectory.geojson");
  EXPECT_EQ(trajectory["features"][0]["geometry"]["coordinates"].size(),
            trajectory["features"][0]["properties"]["times"].size());
}

/// The numbers of a text, in order.
std::vector<double> numbersIn(const std::string& text) {
  std::vector<double> numbers;
  const std::regex number(R"(-?[0-9]+(\.[0-9]+)?([eE][-+]?[0-9]+)?)");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), number);
       it != std::sregex_iterator(); ++it) {
    numbers.push_back(std::stod(it->str()));
  }
  return numbers;
}

TEST(CoverageTool, PlanWithADatumPlacesAMetreMissionThere) {
  // plan --datum of a metre mission writes what plan of its GeoJSON export writes.
  const std::string lake = std::string(KC_SOURCE_DIR) + "/config/missions/lake_30x30.yaml";
  const std::string dir = scratchDir() + "/datum";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  ToolRun run =
      runTool("export '" + lake + "' --datum 47.3769,8.5417 --out '" + dir + "/lake.geojson'");
  ASSERT_EQ(run.exit_status, 0) << run.out;
  run = runTool("plan '" + dir + "/lake.geojson' --out '" + dir + "/geo' --set mission_depth=2");
  ASSERT_EQ(run.exit_status, 0) << run.out;
  run = runTool("plan '" + lake + "' --datum 47.3769,8.5417 --out '" + dir +
                "/placed' --set mission_depth=2");
  ASSERT_EQ(run.exit_status, 0) << run.out;
  // The same waypoints but for the last digits (the export's round trip through WGS84):
  // the same numbers within 1e-6. (A turn's mission waypoints may differ where its two
  // samplings keep its clearance about equally well.)
  const std::vector<double> placed = numbersIn(readText(dir + "/placed/waypoints.geojson"));
  const std::vector<double> geo = numbersIn(readText(dir + "/geo/waypoints.geojson"));
  ASSERT_EQ(placed.size(), geo.size());
  ASSERT_GT(placed.size(), 10u);
  for (std::size_t i = 0; i < placed.size(); ++i) EXPECT_NEAR(placed[i], geo[i], 1e-6) << i;
  for (const char* file : {"mission.plan", "mission.waypoints"}) {
    EXPECT_TRUE(std::filesystem::exists(dir + "/placed/" + file)) << file;
  }
  EXPECT_NE(readText(dir + "/placed/metrics.json").find("\"datum\": [47.3769, 8.5417]"),
            std::string::npos);
  // A geo-referenced mission has its datum; a datum must be LAT,LON in range.
  expectInvalid("plan '" + dir + "/lake.geojson' --datum 47,8 --out '" + dir + "/x'",
                "is geo-referenced already");
  expectInvalid("plan '" + lake + "' --datum 47 --out '" + dir + "/x'", "expected LAT,LON");
  expectInvalid("plan '" + lake + "' --datum 95,8 --out '" + dir + "/x'",
                "the latitude must lie in [-90, 90]");
}

TEST(CoverageTool, PlansTheShippedLakeChartEndToEnd) {
  // config/missions/kleinhesseloher_see.geojson: a lake outline in WGS84 with two islands.
  const std::string dir = scratchDir() + "/lake_chart";
  std::filesystem::remove_all(dir);
  const std::string chart =
      std::string(KC_SOURCE_DIR) + "/config/missions/kleinhesseloher_see.geojson";
  const ToolRun run = runTool("plan '" + chart + "' --out '" + dir + "' --set mission_depth=1.5");
  ASSERT_EQ(run.exit_status, 0) << run.out;
  EXPECT_TRUE(run.err_lines.empty()) << run.err_lines.front();
  const std::string json = readText(dir + "/metrics.json");
  EXPECT_GE(metric(json, "reachable_coverage_percent"), 99.9) << json;
  EXPECT_GT(metric(json, "cells"), 1.0);
  for (const char* file : {"waypoints.geojson", "trajectory.geojson", "plot.png", "mission.plan",
                           "mission.waypoints"}) {
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + file)) << file;
  }
  // At the default depth, 0, the vehicle would stay at the surface: plan says so.
  const ToolRun surface = runTool("plan '" + chart + "' --out '" + dir + "'");
  ASSERT_EQ(surface.exit_status, 0) << surface.out;
  ASSERT_EQ(surface.err_lines.size(), 1u);
  EXPECT_NE(surface.err_lines.front().find("depth 0, the surface: set mission_depth"),
            std::string::npos)
      << surface.err_lines.front();
}

/// A 70 km long lake in WGS84 (a smooth shore of 40 vertices from 6.15 to 7.05 degrees east
/// near 46.4 degrees north, up to 12 km wide), surveyed with a 400 m line sensor: a GeoJSON
/// mission with `properties` added to its polygon feature.
std::string seventyKilometreLake(const std::string& properties) {
  const double pi = std::acos(-1.0);
  constexpr int kVertices = 40;
  std::ostringstream ring;
  ring.precision(9);
  for (int i = 0; i <= kVertices; ++i) {
    const double t = 2.0 * pi * (i % kVertices) / kVertices;
    const double r = 1.0 + 0.12 * std::sin(3.0 * t + 1.7) + 0.07 * std::cos(5.0 * t + 1.3);
    const double longitude = std::round((6.6 + 0.45 * r * std::cos(t)) * 1e6) / 1e6;
    const double latitude =
        std::round((46.4 + 0.05 * r * std::sin(t) + 0.02 * std::cos(2.0 * t)) * 1e6) / 1e6;
    ring << (i ? ", " : "") << "[" << longitude << ", " << latitude << "]";
  }
  return R"({"type": "FeatureCollection", "features": [)"
         R"({"type": "Feature", "properties": {"sensor_model": "line", )"
         R"("lateral_footprint": 400, "wall_distance": 30, "turning_radius": 30, "v_max": 2, )"
         R"("yaw_rate_max": 0.1, "segment_sampling_distance": 20, "arc_sampling_distance": 5)" +
         properties + R"(}, "geometry": {"type": "Polygon", "coordinates": [[)" + ring.str() +
         R"(]]}}, {"type": "Feature", "properties": {"role": "start"}, "geometry": )"
         R"({"type": "Point", "coordinates": [6.2, 46.4]}}, )"
         R"({"type": "Feature", "properties": {"role": "goal"}, "geometry": )"
         R"({"type": "Point", "coordinates": [6.96, 46.4]}}]})";
}

TEST(CoverageTool, PlansASeventyKilometreLakeInTheLocalFrameAndInUtmAlike) {
  const std::string dir = scratchDir() + "/seventy_km";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/local.geojson") << seventyKilometreLake("");
  std::ofstream(dir + "/utm.geojson") << seventyKilometreLake(R"(, "projection": "utm")");
  for (const char* projection : {"local", "utm"}) {
    const ToolRun run = runTool("plan '" + dir + "/" + projection + ".geojson' --out '" + dir +
                                "/" + projection + "' --set mission_depth=5");
    ASSERT_EQ(run.exit_status, 0) << run.out << (run.err_lines.empty() ? "" : run.err_lines[0]);
  }
  const std::string local = readText(dir + "/local/metrics.json");
  const std::string utm = readText(dir + "/utm/metrics.json");
  EXPECT_NE(utm.find("\"projection\": \"utm\""), std::string::npos) << utm;
  EXPECT_NE(utm.find("\"utm_zone\": \"32N\""), std::string::npos) << utm;
  EXPECT_EQ(local.find("utm_zone"), std::string::npos) << local;
  // Both frames are within 1e-3 of true lengths here; the plans agree within 0.2 %. (The
  // UTM grid is turned by the meridian convergence, 1.7 degrees here, against the local
  // frame: on other lakes that turn, like any turn of a map, can change the cells or add a
  // lane. This lake keeps them, so that the comparison measures the projections.)
  EXPECT_EQ(metric(utm, "cells"), metric(local, "cells"));
  EXPECT_EQ(metric(utm, "waypoint_count"), metric(local, "waypoint_count"));
  EXPECT_GT(metric(local, "trajectory_length_m"), 1e6);
  for (const char* key : {"trajectory_length_m", "path_length_m", "traversal_time_s"}) {
    EXPECT_NEAR(metric(utm, key) / metric(local, key), 1.0, 2e-3) << key;
  }
  for (const char* key : {"coverage_percent", "reachable_coverage_percent"}) {
    EXPECT_NEAR(metric(utm, key), metric(local, key), 0.2) << key;
  }
  // The plan's WGS84 outputs lie on the lake in both: their first waypoints agree.
  const YAML::Node local_line = YAML::LoadFile(dir + "/local/waypoints.geojson");
  const YAML::Node utm_line = YAML::LoadFile(dir + "/utm/waypoints.geojson");
  EXPECT_EQ(utm_line["features"][0]["properties"]["utm_zone"].as<std::string>(), "32N");
  const YAML::Node a = local_line["features"][0]["geometry"]["coordinates"][0];
  const YAML::Node b = utm_line["features"][0]["geometry"]["coordinates"][0];
  EXPECT_NEAR(a[0].as<double>(), b[0].as<double>(), 1e-4);
  EXPECT_NEAR(a[1].as<double>(), b[1].as<double>(), 1e-4);
}

TEST(CoverageTool, RejectsBadGeoJsonWithOneLine) {
  const std::string point_start =
      R"({"type": "Feature", "properties": {"role": "start"}, )"
      R"("geometry": {"type": "Point", "coordinates": [8.5417, 47.3769]}})";
  const std::string point_goal =
      R"({"type": "Feature", "properties": {"role": "goal"}, )"
      R"("geometry": {"type": "Point", "coordinates": [8.5418, 47.3770]}})";
  const std::string square =
      R"({"type": "Feature", "properties": {}, "geometry": {"type": "Polygon", "coordinates": )"
      R"([[[8.5416, 47.3768], [8.5420, 47.3768], [8.5420, 47.3772], [8.5416, 47.3772], )"
      R"([8.5416, 47.3768]]]}})";
  const auto collection = [](const std::string& features) {
    return R"({"type": "FeatureCollection", "features": [)" + features + "]}";
  };
  const auto expectInvalidGeoJson = [&](const std::string& text, const std::string& expected) {
    const std::string path = scratchDir() + "/invalid.geojson";
    std::ofstream(path) << text;
    expectInvalid("plan '" + path + "' --out '" + scratchDir() + "/invalid_geo'", expected);
  };
  expectInvalidGeoJson(R"({"type": "Feature"})", "not a GeoJSON FeatureCollection");
  expectInvalidGeoJson("{\"type\": ", "not valid JSON");
  expectInvalidGeoJson(collection(point_start + ", " + point_goal), "no Polygon");
  expectInvalidGeoJson(collection(square + ", " + point_goal),
                       "no Point feature with \"role\": \"start\"");
  expectInvalidGeoJson(collection(square + ", " + point_start),
                       "no Point feature with \"role\": \"goal\"");
  std::string outside = square;
  outside.replace(outside.find("8.5420, 47.3768"), 15, "190.5, 47.3768");
  expectInvalidGeoJson(collection(outside + ", " + point_start + ", " + point_goal),
                       "lies outside [-180, 180] x [-90, 90]");
  // A vertex 2 degrees (150 km) east: 75 km from the extent's centre, the default datum.
  std::string far = square;
  far.replace(far.find("8.5420, 47.3768"), 15, "10.542, 47.3768");
  expectInvalidGeoJson(collection(far + ", " + point_start + ", " + point_goal),
                       "the area is too large");
  std::string unknown = square;
  unknown.replace(unknown.find("\"properties\": {}"), 16, "\"properties\": {\"depth\": 3}");
  expectInvalidGeoJson(collection(unknown + ", " + point_start + ", " + point_goal),
                       "unknown parameter 'depth'");
  expectInvalid("export '" + std::string(KC_SOURCE_DIR) +
                    "/config/missions/lake_30x30.yaml' --datum 95,8 --out '" + scratchDir() +
                    "/x.geojson'",
                "--datum");
}

}  // namespace
