#include <gtest/gtest.h>

#include <string>

#include "polygon_coverage_ros_bridge/decomposition/best_decomposition.h"
#include "polygon_coverage_ros_bridge/mission/mission_file_reader.h"
#include "polygon_coverage_ros_bridge/planner/coverage_planner.h"
#include "polygon_coverage_ros_bridge/sweeps/sweep_pattern.h"
#include "polygon_coverage_ros_bridge/validation/polygon_cleaner.h"
#include "polygon_coverage_ros_bridge/validation/polygon_validator.h"
#include "test/planner/plan_properties.h"

namespace kinematic_coverage {
namespace {

struct PlannedMission {
  Mission mission;
  PolygonWithHoles free_area;
  CoveragePlan plan;
};

PlannedMission planMissionFile(const std::string& name) {
  PlannedMission result;
  result.mission = MissionFileReader().read(std::string(KC_SOURCE_DIR) + "/config/missions/" + name);
  PolygonValidator().validate(result.mission.polygon);
  result.free_area = PolygonCleaner().clean(result.mission.polygon).free_area;
  result.plan = CoveragePlanner(result.mission.parameters)
                    .plan(result.free_area, result.mission.start, result.mission.goal);
  return result;
}

/// The number of lanes the planner lays in the decomposition it chose.
std::size_t laneCount(const PlannedMission& planned) {
  const PlannerParameters& parameters = planned.mission.parameters;
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
  const PlannedMission planned = planMissionFile("lake_30x30.yaml");
  expectValidPlan(planned.free_area, planned.plan, planned.mission.parameters,
                  planned.mission.start, planned.mission.goal);
  EXPECT_GE(planned.plan.cells.size(), 2u);
}

TEST(MissionPlans, Lake7x5HasAtLeastFiveSweeps) {
  const PlannedMission planned = planMissionFile("lake_7_5.yaml");
  expectValidPlan(planned.free_area, planned.plan, planned.mission.parameters,
                  planned.mission.start, planned.mission.goal);
  EXPECT_GE(laneCount(planned), 5u);
}

}  // namespace
}  // namespace kinematic_coverage
