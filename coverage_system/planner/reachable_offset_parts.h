#pragma once

#include <cstddef>
#include <vector>

#include "coverage_system/parameters/planning_options.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "polygon_coverage_ros_bridge/route/offset_part_joiner.h"

namespace kinematic_coverage::core {

/// The part of `parts` nearest to p (0 when p lies in it): the one a robot starting at p
/// enters.
std::size_t nearestPart(const std::vector<PolygonWithHoles>& parts, const Point2& p);

/// The offset free area's `parts` (several, of a cleaned `free_area`) joined for a robot
/// starting at `start`: OffsetPartJoiner with the options' wall distance and gap
/// clearance, anchored at the part nearest the start; from a start nearer the walls than
/// the wall distance, the group holding the most area among those whose parts the start
/// reaches without coming nearer the walls than it starts (a pocket behind a narrow gap may
/// lie nearest). The planner and reachableOffsetParts join alike. Throws SizeLimitError over the
/// joiner's limits, and InternalError when joining valid parts fails (not the user's error).
JoinedOffsetArea joinOffsetParts(const PolygonWithHoles& free_area, const PlanningOptions& options,
                                 const std::vector<PolygonWithHoles>& parts, const Point2& start);

/// The parts of the offset free area of a cleaned `free_area` that count as reachable for a
/// robot starting at `start`, as the planner's plan.offset_parts holds them (docs/REFERENCE.md,
/// Parts): with `offset_parts: all` those joined to the start's part through gaps with at
/// least gap_clearance, with `largest` every part; so that `evaluate`, `simulate` and the
/// trajectory node measure the reachable area as `plan` does. Throws InvalidInputError as
/// computeOffsetFreeArea.
std::vector<PolygonWithHoles> reachableOffsetParts(const PolygonWithHoles& free_area,
                                                   const PlanningOptions& options,
                                                   const Point2& start);

/// The reachable parts (reachableOffsetParts) and the exact offset around them
/// (exactOffsetParts), against which coverage is measured: a plan's offset_parts and
/// exact_offset_parts.
struct ReachableOffset {
  std::vector<PolygonWithHoles> parts;
  std::vector<PolygonWithHoles> exact_parts;
};

/// ReachableOffset of a cleaned `free_area` for a robot starting at `start`.
ReachableOffset reachableOffset(const PolygonWithHoles& free_area, const PlanningOptions& options,
                                const Point2& start);

}  // namespace kinematic_coverage::core
