#include "coverage_system/mission/trajectory_pipeline.h"

#include <chrono>
#include <string>

#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/base/elapsed_seconds.h"
#include "polygon_coverage_ros_bridge/geometry/internal_error.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {

template <typename Step>
auto TrajectoryPipeline::failingAs(const char* stage, const Step& step) const {
  if (origin_ == WaypointOrigin::kUser) return step();
  try {
    return step();
  } catch (const SizeLimitError&) {
    throw;
  } catch (const InvalidInputError& error) {
    throw InternalError(stage, error.what());
  }
}

TrajectoryPipeline::TrajectoryPipeline(const PlannerParameters& parameters,
                                       const std::vector<PolygonWithHoles>& exact_parts,
                                       WaypointOrigin origin)
    : parameters_(parameters),
      exact_parts_(exact_parts),
      origin_(origin),
      options_(trajectoryOptionsOf(parameters, exact_parts)) {
  if (options_.smoothing) {
    sharp_options_ = options_;
    sharp_options_->smoothing = false;
  }
}

MeasuredTrajectory TrajectoryPipeline::run(const std::vector<Pose2>& waypoints,
                                           const PolygonWithHoles& free_area,
                                           bool against_sharp_path) const {
  MeasuredTrajectory measured;
  const auto start = std::chrono::steady_clock::now();
  measured.trajectory = trajectory(waypoints, free_area);
  measured.generation_s = secondsSince(start);
  measured.poses = writtenPoses(measured.trajectory.poses);
  if (const std::optional<GeneratedTrajectory> sharp = sharpTrajectory(waypoints, free_area)) {
    measured.sharp_poses = writtenPoses(sharp->poses);
  }
  measured.coverage =
      measure(free_area, measured.poses, against_sharp_path ? measured.sharp_poses : std::nullopt);
  return measured;
}

GeneratedTrajectory TrajectoryPipeline::trajectory(const std::vector<Pose2>& waypoints,
                                                   const PolygonWithHoles& free_area) const {
  return failingAs(options_.smoothing ? "smooth" : "trajectory",
                   [&] { return TrajectoryGenerator(options_).generate(waypoints, free_area); });
}

std::optional<GeneratedTrajectory> TrajectoryPipeline::sharpTrajectory(
    const std::vector<Pose2>& waypoints, const PolygonWithHoles& free_area) const {
  if (!sharp_options_) return std::nullopt;
  return failingAs("coverage", [&] {
    return TrajectoryGenerator(*sharp_options_).generate(waypoints, free_area);
  });
}

std::vector<Pose2> TrajectoryPipeline::writtenPoses(const std::vector<TrajectoryPose>& trajectory) {
  std::vector<Pose2> poses;
  poses.reserve(trajectory.size());
  for (const TrajectoryPose& pose : trajectory) {
    poses.push_back({pose.x, pose.y, wrapAngle(pose.yaw)});
  }
  return poses;
}

TrajectoryCoverage TrajectoryPipeline::measure(
    const PolygonWithHoles& free_area, const std::vector<Pose2>& poses,
    const std::optional<std::vector<Pose2>>& reference) const {
  return failingAs("coverage", [&] {
    return measureTrajectoryCoverage(free_area, exact_parts_, parameters_, poses, reference);
  });
}

}  // namespace kinematic_coverage::core
