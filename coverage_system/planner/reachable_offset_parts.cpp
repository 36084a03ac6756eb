#include "coverage_system/planner/reachable_offset_parts.h"

#include <algorithm>
#include <limits>
#include <string>

#include "polygon_coverage_ros_bridge/geometry/internal_error.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"

namespace kinematic_coverage::core {

std::size_t nearestPart(const std::vector<PolygonWithHoles>& parts, const Point2& p) {
  std::size_t best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const double d = contains(parts[k], p) ? 0.0 : distanceToBoundary(p, parts[k]);
    if (d < best_distance) {
      best_distance = d;
      best = k;
    }
  }
  return best;
}

namespace {

/// OffsetPartJoiner's join anchored at part `anchor`, its errors as joinOffsetParts names them.
JoinedOffsetArea joinAt(const PolygonWithHoles& free_area, const PlanningOptions& options,
                        const std::vector<PolygonWithHoles>& parts, std::size_t anchor) {
  JoinedOffsetArea joined;
  try {
    joined = OffsetPartJoiner(free_area, options.wall_distance, options.gap_clearance)
                 .join(parts, anchor);
  } catch (const SizeLimitError&) {
    throw;
  } catch (const InvalidInputError& error) {
    throw InternalError("offset", std::string("joining the parts: ") + error.what());
  }
  if (joined.route_area.hull.empty()) {
    throw InternalError("offset", "joining the parts of the offset free area gave no area");
  }
  return joined;
}

/// The parts that a robot starting at `start`, nearer the walls than the wall distance,
/// reaches without coming nearer them than it starts (nor than the gap clearance): those
/// in the piece of the free area's exact offset at the start's own clearance that holds the
/// start. Empty when the start keeps the wall distance.
std::vector<std::size_t> partsInReachOfTheStart(const PolygonWithHoles& free_area,
                                                const PlanningOptions& options,
                                                const std::vector<PolygonWithHoles>& parts,
                                                const Point2& start) {
  const double clearance = distanceToBoundary(start, free_area);
  const double level = std::min(clearance, options.gap_clearance) - kClearanceTolerance;
  if (level <= 0.0 || clearance >= options.wall_distance - kClearanceTolerance) return {};
  for (const PolygonWithHoles& piece :
       WallOffset(free_area).at(level, OffsetCorners::kRoundClear).parts) {
    if (!contains(piece, start, kClearanceTolerance)) continue;
    std::vector<std::size_t> in_reach;
    for (std::size_t k = 0; k < parts.size(); ++k) {
      if (contains(piece, parts[k].hull.front())) in_reach.push_back(k);
    }
    return in_reach;
  }
  return {};
}

double joinedArea(const JoinedOffsetArea& joined, const std::vector<PolygonWithHoles>& parts) {
  double total = 0.0;
  for (std::size_t k : joined.joined_parts) total += area(parts[k]);
  return total;
}

}  // namespace

JoinedOffsetArea joinOffsetParts(const PolygonWithHoles& free_area, const PlanningOptions& options,
                                 const std::vector<PolygonWithHoles>& parts, const Point2& start) {
  JoinedOffsetArea best = joinAt(free_area, options, parts, nearestPart(parts, start));
  // From the wall band, the nearest part may be a pocket behind a narrow gap; every group
  // of parts the start reaches at its own clearance is as much the start's.
  std::vector<bool> covered(parts.size(), false);
  for (std::size_t k : best.joined_parts) covered[k] = true;
  double best_area = joinedArea(best, parts);
  for (std::size_t k : partsInReachOfTheStart(free_area, options, parts, start)) {
    if (covered[k]) continue;
    JoinedOffsetArea joined = joinAt(free_area, options, parts, k);
    for (std::size_t j : joined.joined_parts) covered[j] = true;
    const double joined_area = joinedArea(joined, parts);
    if (joined_area > best_area) {
      best_area = joined_area;
      best = std::move(joined);
    }
  }
  return best;
}

std::vector<PolygonWithHoles> reachableOffsetParts(const PolygonWithHoles& free_area,
                                                   const PlanningOptions& options,
                                                   const Point2& start) {
  std::vector<PolygonWithHoles> parts =
      computeOffsetFreeArea(free_area, options.wall_distance, options.offset_miter_limit).parts;
  if (parts.size() == 1 || options.offset_parts == OffsetParts::kLargest) return parts;
  const JoinedOffsetArea joined = joinOffsetParts(free_area, options, parts, start);
  std::vector<PolygonWithHoles> reachable;
  for (std::size_t k : joined.joined_parts) reachable.push_back(parts[k]);
  return reachable;
}

ReachableOffset reachableOffset(const PolygonWithHoles& free_area, const PlanningOptions& options,
                                const Point2& start) {
  ReachableOffset offset;
  offset.parts = reachableOffsetParts(free_area, options, start);
  offset.exact_parts = exactOffsetParts(free_area, options.wall_distance, offset.parts);
  return offset;
}

}  // namespace kinematic_coverage::core
