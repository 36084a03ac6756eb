#include "coverage_system/planner/reachable_offset_parts.h"

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

JoinedOffsetArea joinOffsetParts(const PolygonWithHoles& free_area, const PlanningOptions& options,
                                 const std::vector<PolygonWithHoles>& parts, const Point2& start) {
  JoinedOffsetArea joined;
  try {
    joined = OffsetPartJoiner(free_area, options.wall_distance, options.gap_clearance)
                 .join(parts, nearestPart(parts, start));
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

std::vector<PolygonWithHoles> reachableOffsetParts(const PolygonWithHoles& free_area,
                                                   const PlanningOptions& options,
                                                   const Point2& start) {
  std::vector<PolygonWithHoles> parts =
      computeOffsetFreeArea(free_area, options.wall_distance).parts;
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
