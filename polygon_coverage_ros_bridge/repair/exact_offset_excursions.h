#pragma once

#include <optional>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/edge_grid.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// Straight excursions out of the mitred offset free area that still keep the wall
/// distance. The mitred offset, which the planner sweeps and routes in, stops short of the
/// exact offset wherever a wall's corner bulges into the free area (by a fifth of a square
/// wall distance at a right angle, by many wall distances at a spike) and at the mouth of
/// a slot narrower than two wall distances, and the reachable area there may lie out of
/// sight of the mitred boundary. An excursion runs from a point of the mitred boundary
/// out to where the walls come as near as the wall distance, by steps that each keep it
/// (from a point d from the walls, a step of d less the wall distance: a distance changes
/// by at most the length moved). From a corner where the mitred boundary turns away from
/// its inside it runs along the corner's outer bisector, which at a mitre points at the
/// wall's corner: the excursion ends on the exact offset's round corner.
class ExactOffsetExcursions {
 public:
  /// No excursions (the offset by a wall distance of 0 is exact).
  ExactOffsetExcursions() = default;

  /// Excursions from the offset of `free_area` (cleaned: its hull and holes are the walls)
  /// by `wall_distance`, `min_length` to `max_length` m long.
  ExactOffsetExcursions(const PolygonWithHoles& free_area, double wall_distance, double min_length,
                        double max_length);

  /// The far end of the excursion from `corner`, a vertex of a ring whose inside lies to
  /// its left (a hull counter-clockwise, a hole clockwise) between `before` and `after`;
  /// none where the ring turns toward its inside or runs straight on, or where the
  /// excursion would be shorter than min_length.
  std::optional<Point2> apex(const Point2& before, const Point2& corner, const Point2& after) const;

  /// The far end of the excursion from `from` (a point at least the wall distance from the
  /// walls) along `direction`; none for a zero direction or an excursion shorter than
  /// min_length.
  std::optional<Point2> toward(const Point2& from, const Point2& direction) const;

  /// True when no point of the segment from a to b comes nearer to the walls than the wall
  /// distance: a straight way to or from an excursion's far end that keeps it.
  bool keepsDistance(const Point2& a, const Point2& b) const;

  /// The far ends of the legs of a way from `from` (a point at least the wall distance from
  /// the walls) toward `target`, which keeps the wall distance: first the excursion
  /// toward() it, then, while the way ends farther than `reach` from it, more legs, each the
  /// longest that keeps the distance in its direction, of thirteen a quarter radian apart
  /// centred on the target's, whose end comes nearest to it; the way follows a funnel that the
  /// walls bend (toward a gap narrower than two wall distances), where one straight excursion stops
  /// short or cannot start. Ends where no leg comes min_length nearer; empty when none does.
  std::vector<Point2> walk(const Point2& from, const Point2& target, double reach) const;

 private:
  /// The far end of the longest segment from `from` along the unit `direction`, at most
  /// max_length long, that keeps the wall distance (`from` itself where none does).
  Point2 farthestKeeping(const Point2& from, const Point2& direction) const;

  /// The distance from p to the nearest wall, or `reach` when none lies nearer.
  double wallDistance(const Point2& p, double reach) const;

  std::vector<Point2> from_;  ///< wall i runs from from_[i] to to_[i]
  std::vector<Point2> to_;
  EdgeGrid grid_;
  double wall_distance_ = 0.0;
  double min_length_ = 0.0;
  double max_length_ = 0.0;
};

}  // namespace kinematic_coverage::core
