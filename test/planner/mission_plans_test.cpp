#include <gtest/gtest.h>

#include <string>

#include "polygon_coverage_ros_bridge/decomposition/best_decomposition.h"
#include "polygon_coverage_ros_bridge/mission/mission_file_reader.h"
#include "polygon_coverage_ros_bridge/mission/mission_planner.h"
#include "polygon_coverage_ros_bridge/sweeps/sweep_pattern.h"
#include "test/planner/plan_properties.h"

namespace kinematic_coverage {
namespace {

/// The number of lanes the planner lays in the decomposition it chose.
std::size_t laneCount(const Mission& mission, const PlannedMission& planned) {
  const PlannerParameters& parameters = mission.parameters;
  const FrustumSensor sensor = FrustumSensor::fromParameters(parameters);
  const SweepPatternGenerator generator(
      sensor, SweepPatternGenerator::laneEndInset(sensor, parameters.wall_distance));
  std::size_t lanes = 0;
  for (const Cell& cell :
       computeBestDecomposition(planned.plan.offset_free_area, DecompositionType::kBoustrophedon)
           .cells) {
    lanes += generator.lanes(cell.polygon, cell.sweep_directions.front()).size();
  }
  return lanes;
}

TEST(MissionPlans, Lake30x30) {
  const Mission mission =
      MissionFileReader().read(std::string(KC_SOURCE_DIR) + "/config/missions/lake_30x30.yaml");
  const PlannedMission planned = planMission(mission);
  expectValidPlan(planned.free_area, planned.plan, mission.parameters, mission.start, mission.goal);
  EXPECT_GE(planned.plan.cells.size(), 2u);
}

TEST(MissionPlans, Lake7x5HasAtLeastFiveSweeps) {
  const Mission mission =
      MissionFileReader().read(std::string(KC_SOURCE_DIR) + "/config/missions/lake_7_5.yaml");
  const PlannedMission planned = planMission(mission);
  expectValidPlan(planned.free_area, planned.plan, mission.parameters, mission.start, mission.goal);
  EXPECT_GE(laneCount(mission, planned), 5u);
}

}  // namespace
}  // namespace kinematic_coverage
