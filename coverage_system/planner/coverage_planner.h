#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "coverage_system/parameters/planner_parameters.h"
#include "coverage_system/parameters/planning_options.h"
#include "coverage_system/planner/planning_limits.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "polygon_coverage_ros_bridge/route/offset_part_joiner.h"

namespace kinematic_coverage::core {

/// One stage of planning, for log lines and status messages.
struct PlanningStage {
  std::string name;  ///< "offset", "simplify" (boundary_simplification > 0), "decompose",
                     ///< "sweeps", "transitions", "solve",
                     ///< "alternative" (cell_joining longest_overlap), "path", "repair"
  double duration_s = 0.0;
  std::string summary;  ///< one line: what the stage produced
};

/// Called as each stage finishes, for progress lines while a large plan runs.
using StageCallback = std::function<void(const PlanningStage&)>;

/// A coverage waypoint path and what the planner learned on the way.
struct CoveragePlan {
  /// Waypoints; each yaw is the heading of the leg leaving it (the incoming heading at
  /// the last one); docs/REFERENCE.md, File formats.
  std::vector<Pose2> waypoints;
  /// Index range [first_inside, last_inside] of the waypoints within the offset free
  /// area; legs before and after it join a start or goal outside that area.
  std::size_t first_inside = 0;
  std::size_t last_inside = 0;
  /// The offset free area (docs/REFERENCE.md, Geometry and input rules), the largest part
  /// first: every part with offset_parts `largest`, planned or not; with `all` the parts
  /// reachable from the start through gaps with at least gap_clearance. The reachable area
  /// is grown from them.
  std::vector<PolygonWithHoles> offset_parts;
  /// The exact offset around offset_parts (exactOffsetParts): every point at least
  /// wall_distance from the walls in the parts reached, from which the coverage report grows
  /// the reachable area.
  std::vector<PolygonWithHoles> exact_offset_parts;
  /// The parts of the offset free area that are not entered: beyond gaps narrower than
  /// gap_clearance from the start (offset_parts `all`). They count as unreachable.
  std::vector<PolygonWithHoles> unreachable_parts;
  /// Where transitions run: the planned parts joined by corridors through the gaps between
  /// them. Every leg from first_inside to last_inside lies in it.
  PolygonWithHoles route_area;
  /// The gaps (with at least gap_clearance) that transits pass between parts.
  std::vector<OffsetGap> gaps;
  /// The cells of the chosen decomposition, counter-clockwise.
  std::vector<Ring> cells;
  double path_length_m = 0.0;
  /// Time cost of the waypoint path: rest-to-rest trapezoidal profile per segment.
  double time_cost_s = 0.0;
  double planning_time_s = 0.0;
  /// True when the generalized TSP's safety cap ended its search (the tour is the best
  /// found by then); a warning says so.
  bool gtsp_time_capped = false;
  /// One line per warning (gaps between parts of the offset area, dropped parts, ...).
  std::vector<std::string> warnings;
  /// The stages in order, with their durations.
  std::vector<PlanningStage> stages;
};

/// Plans a coverage path over a cleaned free area (Thesis section 3.1, its reference [10]):
/// wall offset, cell decomposition over candidate directions, sweep patterns per cell,
/// and a generalized TSP over them from start to goal.
class CoveragePlanner {
 public:
  /// A planner with these options; each stage is handed its part of them.
  explicit CoveragePlanner(PlanningOptions options);

  /// A planner with the options of `parameters` (planningOptionsOf, which checks them once).
  /// Throws InvalidInputError for parameters out of range.
  explicit CoveragePlanner(const PlannerParameters& parameters);

  /// Plans over `free_area` (cleaned: CCW hull, CW holes, no crossings).
  /// Throws InvalidInputError for an impossible request (empty offset free area, a
  /// start or goal whose joining leg crosses a hole, ...) and for a plan over the size
  /// limits of planning_limits.h, saying by how much and what would reduce it. When every kept lane
  /// direction would give the generalized TSP more than kMaxGtspNodes nodes, cells keep
  /// only their best directions (a warning says how many were dropped).
  /// `on_stage`, when given, hears of every stage as it finishes.
  CoveragePlan plan(const PolygonWithHoles& free_area, const Point2& start, const Point2& goal,
                    const StageCallback& on_stage = {}) const;

  /// As plan(), covering only the parts of the offset free area inside `coverage_region`
  /// (replanning: the area still to see). The parts, however many, are swept in
  /// one generalized TSP; transitions use the whole offset free area. With nothing to
  /// cover, the path goes from start to goal.
  CoveragePlan planRegion(const PolygonWithHoles& free_area,
                          const std::vector<PolygonWithHoles>& coverage_region, const Point2& start,
                          const Point2& goal, const StageCallback& on_stage = {}) const;

 private:
  /// Both entry points: the whole offset free area when `coverage_region` is null.
  CoveragePlan planParts(const PolygonWithHoles& free_area,
                         const std::vector<PolygonWithHoles>* coverage_region, const Point2& start,
                         const Point2& goal, const StageCallback& on_stage) const;

 private:
  PlanningOptions options_;
};

}  // namespace kinematic_coverage::core
