#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "coverage_system/parameters/planner_parameters.h"
#include "coverage_system/parameters/planning_options.h"
#include "coverage_system/planner/coverage_planner.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/replanning/remaining_area.h"
#include "trajectory_generation_tools/replanning/visited_history.h"

namespace kinematic_coverage::core {

/// A replanned mission (thesis section 3.4) and what it was made from.
struct ReplannedMission {
  PolygonWithHoles free_area;     ///< the updated polygon, validated and cleaned
  RemainingArea remaining;        ///< the area still to see
  Point2 start = Point2::Zero();  ///< where the new plan starts: the last visited pose
  CoveragePlan plan;              ///< over the remaining parts, from start to the goal
  std::vector<std::string> warnings;
  double planning_time_s = 0.0;  ///< validation, cleaning, remaining area and planning
};

/// Replans after obstacles moved: validates and cleans the updated polygon, computes the
/// remaining area from the visited poses (RemainingAreaCalculator, `replanning_method`),
/// and plans its parts in one generalized TSP from the last visited pose to the goal.
/// A last pose that a moved obstacle now covers starts from the nearest point outside it
/// when that is within `wall_distance`; deeper inside is invalid input
/// (docs/REFERENCE.md, Geometry and input rules).
class Replanner {
 public:
  /// A replanner that plans with `planning` and takes the remaining area with `remaining`.
  Replanner(PlanningOptions planning, RemainingAreaOptions remaining);

  /// The same with the options of `parameters` (checked once). Throws InvalidInputError
  /// for parameters out of range.
  explicit Replanner(const PlannerParameters& parameters);

  /// Throws InvalidInputError for an invalid polygon, no or non-finite visited poses, a
  /// goal inside a hole, or a start as described above.
  ReplannedMission replan(const PolygonWithHoles& updated_polygon,
                          const std::vector<Pose2>& visited, const Point2& goal,
                          const StageCallback& on_stage = {}) const;

  /// The same from a bounded history (VisitedHistory): its seen area by its recorded sensor.
  ReplannedMission replan(const PolygonWithHoles& updated_polygon, const VisitedHistory& visited,
                          const Point2& goal, const StageCallback& on_stage = {}) const;

 private:
  /// Validates, cleans, takes the remaining area from `remaining_of` (given the cleaned
  /// free area) and plans it from `last`, the newest of `visited_count` poses.
  ReplannedMission replanFrom(
      const PolygonWithHoles& updated_polygon, const Pose2& last, std::size_t visited_count,
      const Point2& goal, const StageCallback& on_stage,
      const std::function<RemainingArea(const PolygonWithHoles&)>& remaining_of) const;

  PlanningOptions planning_options_;
  RemainingAreaOptions remaining_options_;
};

}  // namespace kinematic_coverage::core
