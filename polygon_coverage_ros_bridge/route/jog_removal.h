#pragma once

#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "polygon_coverage_ros_bridge/route/visibility_graph.h"

namespace kinematic_coverage::core {

/// Removes the short jogs of a waypoint path that no robot with a turning radius can
/// smooth: where lanes of neighbouring cells or a lane and its transition meet a
/// few centimetres apart, the path bends twice within less than a turning radius, and
/// Algorithm 1 can smooth neither bend. A waypoint goes when one of its legs is shorter
/// than `short_leg`, it lies at most `max_deviation` from the straight segment that would
/// replace its two legs, and that segment stays inside the offset free area. With
/// `max_deviation` at most half the sensor's lateral overlap ((W - s) / 2), the shifted
/// stretch of path still sees what its neighbouring lanes rely on.
class JogRemoval {
 public:
  /// `graph` is the offset free area's visibility graph (it must outlive this object).
  /// Throws InvalidInputError for a negative or non-finite `short_leg` or `max_deviation`.
  JogRemoval(const VisibilityGraph& graph, double short_leg, double max_deviation);

  /// The path without its removable jogs. Waypoints whose `keep` flag is set (entry and
  /// exit of the offset free area, start and goal) always stay; the result's flags are
  /// written to `kept` when it is not null. `keep` has one flag per waypoint. Waypoints
  /// flagged in `pinned` (when given, one flag per waypoint) stay too, but without a flag
  /// in `kept`: jogs whose shift would leave area unseen (UnseenAreaRepair).
  std::vector<Point2> apply(const std::vector<Point2>& path, const std::vector<bool>& keep,
                            std::vector<bool>* kept = nullptr,
                            const std::vector<bool>* pinned = nullptr) const;

 private:
  /// True when waypoint b may be dropped between a and c, the waypoints `dropped` before
  /// it (between a and b) staying within the deviation bound too.
  bool removable(const Point2& a, const Point2& b, const Point2& c,
                 const std::vector<Point2>& dropped) const;

  const VisibilityGraph& graph_;
  double short_leg_;
  double max_deviation_;
};

}  // namespace kinematic_coverage::core
