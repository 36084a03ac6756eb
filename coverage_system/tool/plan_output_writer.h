#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "coverage_system/mission/mission.h"
#include "coverage_system/mission/mission_frame.h"
#include "coverage_system/parameters/planner_parameters.h"
#include "coverage_system/planner/coverage_planner.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/coverage/coverage_evaluator.h"
#include "trajectory_generation_tools/smoothing/path_smoother.h"

namespace kinematic_coverage::core {

/// What `plan` and `replan` write about a plan.
struct PlanOutputRequest {
  const PlannerParameters* parameters = nullptr;
  const PolygonWithHoles* free_area = nullptr;  ///< cleaned: collisions and coverage
  const CoveragePlan* plan = nullptr;
  double planning_time_s = 0.0;
  Point2 start = Point2::Zero();
  Point2 goal = Point2::Zero();
  std::string title;  ///< the plot's first line
  /// Replanning: the poses visited before the plan; metrics.json then also has
  /// `combined_coverage_percent` (visited and new trajectory together), which the plot's
  /// heatmap shows.
  std::optional<std::vector<Pose2>> visited;
  /// A geo-referenced mission's frame (MissionFrame: datum and projection): metrics.json
  /// records it, and the GeoJSON outputs and the vehicle's mission files are written too.
  std::string frame_id = "map";
  std::optional<MissionFrame> frame;
};

/// What writePlanOutputs wrote and found.
struct PlanOutputs {
  std::vector<std::string> files;     ///< the written paths
  std::vector<std::string> warnings;  ///< e.g. reachable area left unseen (no "warning: ")
  /// The figures of metrics.json that benchmarks compare: the trajectory's coverage (the
  /// new trajectory's alone when replanning), its turns and its traversal time.
  CoverageReport coverage;
  SmoothingStatistics turns;
  double traversal_time_s = 0.0;
  /// The trajectory's closest approach to the hull and holes (metrics.json's
  /// min_obstacle_clearance_m; infinity where meaningless).
  double min_obstacle_clearance_m = 0.0;
  /// What a smoothed trajectory fails to see of what its unsmoothed one sees (with the
  /// visited poses when replanning); none when unsmoothed.
  std::optional<LostArea> smoothing_loss;
};

/// Smooths, samples and times the plan's trajectory (TrajectoryGenerator), measures its
/// coverage, and writes DIR/waypoints.csv, DIR/trajectory.csv, DIR/metrics.json and
/// DIR/plot.png (docs/REFERENCE.md, File formats), with one progress line per stage on `out`;
/// for a geo-referenced mission also DIR/waypoints.geojson (times: the planner's rest-to-rest
/// time cost up to each waypoint) and DIR/trajectory.geojson (times: the poses' t).
/// The trajectory files hold the poses that `trajectory_output_spacing` keeps
/// (TrajectoryThinning); the figures, the plot and the mission files use every pose.
/// A trajectory that sees less than kReachableCoverageBarPercent of the reachable area
/// gives a warning, and the plot outlines the largest unseen region; a smoothed one is
/// measured against its unsmoothed trajectory too (metrics.json's smoothing_lost_area_m2
/// and smoothing_lost_reachable_area_m2), with smoothingLossWarning's warning. Throws
/// InvalidInputError when a file cannot be written.
PlanOutputs writePlanOutputs(const PlanOutputRequest& request, const std::string& out_dir,
                             std::ostream& out);

}  // namespace kinematic_coverage::core
