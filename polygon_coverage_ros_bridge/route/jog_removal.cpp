#include "polygon_coverage_ros_bridge/route/jog_removal.h"

#include <algorithm>
#include <cmath>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {

JogRemoval::JogRemoval(const VisibilityGraph& graph, double short_leg, double max_deviation)
    : graph_(graph), short_leg_(short_leg), max_deviation_(max_deviation) {
  if (!std::isfinite(short_leg) || short_leg < 0.0) {
    throw InvalidInputError("jog removal: the short leg length must be >= 0 and finite");
  }
  if (!std::isfinite(max_deviation) || max_deviation < 0.0) {
    throw InvalidInputError("jog removal: the largest deviation must be >= 0 and finite");
  }
}

bool JogRemoval::removable(const Point2& a, const Point2& b, const Point2& c,
                           const std::vector<Point2>& dropped) const {
  const double shorter = std::min((b - a).norm(), (c - b).norm());
  if (shorter >= short_leg_) return false;
  auto deviates = [&](const Point2& p) {
    return (p - closestPointOnSegment(p, a, c)).norm() > max_deviation_;
  };
  if (deviates(b)) return false;
  for (const Point2& p : dropped) {
    if (deviates(p)) return false;
  }
  return graph_.visible(a, c);
}

std::vector<Point2> JogRemoval::apply(const std::vector<Point2>& path,
                                      const std::vector<bool>& keep, std::vector<bool>* kept,
                                      const std::vector<bool>* pinned) const {
  if (keep.size() != path.size() || (pinned != nullptr && pinned->size() != path.size())) {
    throw InvalidInputError("jog removal: one keep flag per waypoint expected");
  }
  const auto stays = [&](std::size_t i) { return keep[i] || (pinned != nullptr && (*pinned)[i]); };
  // The kept waypoints, each with the original waypoints dropped between it and the next
  // kept one: every dropped waypoint stays within max_deviation of the final path, so
  // removals never add up to a larger shift.
  struct KeptWaypoint {
    Point2 point;
    bool protect;
    bool stays;
    std::vector<Point2> dropped_after;
  };
  std::vector<KeptWaypoint> result;
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (!result.empty() && i + 1 < path.size() && !stays(i) &&
        removable(result.back().point, path[i], path[i + 1], result.back().dropped_after)) {
      result.back().dropped_after.push_back(path[i]);
      continue;
    }
    // The waypoint stays; the previous one may have become removable now that its next
    // neighbour is this one (a jog whose short leg ends here).
    while (result.size() >= 2 && !result.back().stays) {
      const KeptWaypoint& before = result[result.size() - 2];
      std::vector<Point2> dropped = before.dropped_after;
      dropped.insert(dropped.end(), result.back().dropped_after.begin(),
                     result.back().dropped_after.end());
      if (!removable(before.point, result.back().point, path[i], dropped)) break;
      dropped.push_back(result.back().point);
      result.pop_back();
      result.back().dropped_after = std::move(dropped);
    }
    result.push_back({path[i], keep[i], stays(i), {}});
  }
  std::vector<Point2> points;
  if (kept != nullptr) kept->clear();
  for (const KeptWaypoint& waypoint : result) {
    points.push_back(waypoint.point);
    if (kept != nullptr) kept->push_back(waypoint.protect);
  }
  return points;
}

}  // namespace kinematic_coverage::core
