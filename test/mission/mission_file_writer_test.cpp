#include "coverage_system/mission/mission_file_writer.h"

#include <gtest/gtest.h>

#include <string>

#include "coverage_system/mission/mission_file_reader.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {
namespace {

Mission lakeWithAnIsland() {
  Mission mission;
  mission.frame_id = "survey's frame";
  mission.polygon.hull = {{0, 0}, {30.1, 0}, {30.1, 0.1 + 0.2}, {31, 30}, {0, 30}};
  mission.polygon.holes = {{{8, 8}, {12, 8}, {12, 12}, {8, 12.000000000000002}}};
  mission.start = {1.0 / 3.0, 1};
  mission.goal = {29, 29.7};
  mission.parameters.turning_radius = 0.7;
  mission.parameters.smoothing = false;
  mission.parameters.decomposition_type = "trapezoidal";
  mission.parameters.boundary_simplification = 0.05;
  return mission;
}

TEST(MissionFileWriter, WritesAMissionThatReadsBackExactly) {
  const Mission mission = lakeWithAnIsland();
  const Mission read =
      MissionFileReader().parse(MissionFileWriter::text(mission, "saved by a test"), "saved.yaml");
  EXPECT_EQ(read.frame_id, mission.frame_id);
  EXPECT_EQ(read.polygon.hull, mission.polygon.hull);
  EXPECT_EQ(read.polygon.holes, mission.polygon.holes);
  EXPECT_EQ(read.start, mission.start);
  EXPECT_EQ(read.goal, mission.goal);
  for (const std::string& name : MissionFileReader::parameterNames()) {
    EXPECT_EQ(MissionFileReader::parameterText(read.parameters, name),
              MissionFileReader::parameterText(mission.parameters, name))
        << name;
  }
}

TEST(MissionFileWriter, WritesOnlyTheParametersThatDifferFromTheDefaults) {
  const std::string text = MissionFileWriter::text(lakeWithAnIsland(), "");
  EXPECT_EQ(text.rfind("frame_id: ", 0), 0u) << "no comment line without a comment";
  EXPECT_NE(text.find("\nturning_radius: 0.7\n"), std::string::npos);
  EXPECT_NE(text.find("\nsmoothing: false\n"), std::string::npos);
  EXPECT_NE(text.find("\ndecomposition_type: trapezoidal\n"), std::string::npos);
  EXPECT_NE(text.find("\nboundary_simplification: 0.05\n"), std::string::npos);
  EXPECT_EQ(text.find("v_max"), std::string::npos);
  // A mission at the defaults has no parameter lines after its goal.
  const std::string defaults = MissionFileWriter::text(Mission{}, "");
  const std::string tail = "holes: []\nstart: [0, 0]\ngoal: [0, 0]\n";
  ASSERT_GE(defaults.size(), tail.size());
  EXPECT_EQ(defaults.substr(defaults.size() - tail.size()), tail);
}

TEST(MissionFileWriter, APathThatCannotBeWrittenIsNamed) {
  try {
    MissionFileWriter::write(lakeWithAnIsland(), "/nonexistent-directory/mission.yaml", "");
    FAIL() << "no error";
  } catch (const InvalidInputError& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent-directory/mission.yaml"),
              std::string::npos);
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
