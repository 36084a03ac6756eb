#pragma once

#include <string>
#include <vector>

#include "coverage_system/mission/mission_file_reader.h"
#include "coverage_system/mission/mission_planner.h"
#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"
#include "trajectory_generation_tools/coverage/coverage_evaluator.h"
#include "trajectory_generation_tools/trajectory/trajectory_generator.h"

namespace kinematic_coverage::core::testing {

/// The replanning drift scenario on the lake mission: the robot followed the first
/// `followed_share` of the planned trajectory, then both obstacles moved by `shift`.
struct DriftScenario {
  Mission mission;
  std::vector<Pose2> visited;
  PolygonWithHoles updated;  ///< the mission's polygon with the holes moved
};

inline DriftScenario lakeDriftScenario(double followed_share, const Point2& shift) {
  DriftScenario scenario;
  scenario.mission =
      MissionFileReader().read(std::string(KC_SOURCE_DIR) + "/config/missions/lake_30x30.yaml");
  const PlannedMission planned = planMission(scenario.mission);
  const GeneratedTrajectory trajectory =
      TrajectoryGenerator(trajectoryOptionsOf(scenario.mission.parameters))
          .generate(planned.plan.waypoints, planned.free_area);
  const std::size_t count =
      static_cast<std::size_t>(followed_share * static_cast<double>(trajectory.poses.size()));
  for (std::size_t i = 0; i < count; ++i) {
    const TrajectoryPose& pose = trajectory.poses[i];
    scenario.visited.push_back({pose.x, pose.y, pose.yaw});
  }
  scenario.updated = scenario.mission.polygon;
  for (Ring& hole : scenario.updated.holes) {
    for (Point2& p : hole) p += shift;
  }
  return scenario;
}

/// Seen share (percent) of the reachable area of `free_area` by the visited poses and the
/// new trajectory together, on a 5 cm raster.
inline double combinedReachableCoverage(const PolygonWithHoles& free_area,
                                        const PlannerParameters& parameters,
                                        const std::vector<Pose2>& visited,
                                        const std::vector<TrajectoryPose>& trajectory) {
  const OffsetFreeArea offset = computeOffsetFreeArea(free_area, parameters.wall_distance);
  RasterResolution resolution;
  resolution.cell_size = 0.05;
  const CoverageEvaluator evaluator(free_area, offset.parts, sensorOf(parameters), resolution);
  SeenArea seen = evaluator.seeTrajectory(visited);
  std::vector<Pose2> poses;
  for (const TrajectoryPose& pose : trajectory) poses.push_back({pose.x, pose.y, pose.yaw});
  seen.addTrajectory(poses, sensorOf(parameters));
  return seen.coveragePercent(evaluator.reachableArea());
}

}  // namespace kinematic_coverage::core::testing
