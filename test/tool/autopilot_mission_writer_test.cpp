#include "coverage_system/tool/autopilot_mission_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace kinematic_coverage::core {
namespace {

std::vector<std::vector<std::string>> tabFields(const std::string& text) {
  std::vector<std::vector<std::string>> lines;
  std::istringstream stream(text);
  std::string line;
  while (std::getline(stream, line)) {
    std::vector<std::string> fields;
    std::istringstream fields_stream(line);
    std::string field;
    while (std::getline(fields_stream, field, '\t')) fields.push_back(field);
    lines.push_back(fields);
  }
  return lines;
}

AutopilotMission threeWaypoints() {
  AutopilotMission mission;
  mission.waypoints = {{{0, 0}, 0.5, false}, {{10, 0}, 0.5, true}, {{10, 10}, 0.25, false}};
  return mission;
}

TEST(AutopilotMissionWriter, WritesTheWplItemsWithSpeedChangesHoldsAndDepth) {
  const AutopilotMissionWriter writer(MissionFrame({47.0, 8.0}, MapProjection::kLocal), {3.0, 2.0},
                                      threeWaypoints());
  // Speed 0.5, waypoint, waypoint, speed 0.25, waypoint.
  EXPECT_EQ(writer.itemCount(), 5u);
  const auto lines = tabFields(writer.waypointsText());
  ASSERT_EQ(lines.size(), 7u);
  EXPECT_EQ(lines[0], std::vector<std::string>{"QGC WPL 110"});
  for (std::size_t i = 1; i < lines.size(); ++i) {
    ASSERT_EQ(lines[i].size(), 12u) << i;
    EXPECT_EQ(lines[i][0], std::to_string(i - 1));
    EXPECT_EQ(lines[i][1], i == 1 ? "1" : "0");  // the home line is the current one
    EXPECT_EQ(lines[i][11], "1");                // autocontinue
  }
  // The home line: the first waypoint, global frame, at the surface.
  EXPECT_EQ(lines[1][3], "16");
  EXPECT_EQ(lines[1][10], "0");
  // DO_CHANGE_SPEED: ground speed 0.5 m/s, throttle unchanged.
  EXPECT_EQ(
      (std::vector<std::string>{lines[2][2], lines[2][3], lines[2][4], lines[2][5], lines[2][6]}),
      (std::vector<std::string>{"2", "178", "1", "0.5", "-1"}));
  // NAV_WAYPOINT: relative-altitude frame, hold 1 s only where held, acceptance radius 2 m,
  // altitude -3 m (3 m deep).
  for (std::size_t line : {3u, 4u, 6u}) {
    EXPECT_EQ(lines[line][2], "3");
    EXPECT_EQ(lines[line][3], "16");
    EXPECT_EQ(lines[line][4], line == 4 ? "1" : "0");
    EXPECT_EQ(lines[line][5], "2");
    EXPECT_EQ(lines[line][10], "-3");
  }
  EXPECT_EQ(lines[5][5], "0.25");
  // The first waypoint is the datum; 10 m east is about 1.3e-4 degrees of longitude.
  EXPECT_NEAR(std::stod(lines[3][8]), 47.0, 1e-9);
  EXPECT_NEAR(std::stod(lines[3][9]), 8.0, 1e-9);
  EXPECT_NEAR(std::stod(lines[4][9]) - 8.0, 10.0 / (111320.0 * std::cos(47.0 * M_PI / 180.0)),
              1e-6);
}

TEST(AutopilotMissionWriter, WritesDepthZeroAsAltitudeZero) {
  const AutopilotMissionWriter writer(MissionFrame({47.0, 8.0}, MapProjection::kLocal), {0.0, 2.0},
                                      threeWaypoints());
  const auto lines = tabFields(writer.waypointsText());
  EXPECT_EQ(lines[3][10], "0");
}

TEST(AutopilotMissionWriter, ThePlanFileHoldsTheSameItems) {
  const AutopilotMissionWriter writer(MissionFrame({47.0, 8.0}, MapProjection::kLocal), {3.0, 2.0},
                                      threeWaypoints());
  const std::string plan = writer.planJson();
  EXPECT_NE(plan.find("\"fileType\": \"Plan\""), std::string::npos);
  EXPECT_NE(plan.find("\"vehicleType\": 12"), std::string::npos);
  EXPECT_NE(plan.find("\"corner_cutting_radius_m\": 2"), std::string::npos);
  std::size_t items = 0;
  for (std::size_t at = plan.find("\"SimpleItem\""); at != std::string::npos;
       at = plan.find("\"SimpleItem\"", at + 1)) {
    ++items;
  }
  EXPECT_EQ(items, 5u);
}

}  // namespace
}  // namespace kinematic_coverage::core
