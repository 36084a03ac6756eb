#pragma once

#include <visualization_msgs/MarkerArray.h>

#include <cstddef>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::nodes {

/// How large rviz draws a map's markers and how many points they may have: line widths and
/// sphere sizes grow with the map's extent, so that a lake's markers stay visible when it
/// is shown whole, and each node's marker array keeps to kPointBudget points, so that rviz
/// stays responsive on a chart of thousands of cells.
class MarkerScale {
 public:
  /// Most points of one node's marker array (coverage_planner's and
  /// smooth_trajectory_generator's together stay under twice this).
  static constexpr std::size_t kPointBudget = 10000;
  /// Maps up to this extent (m) keep the base sizes.
  static constexpr double kReferenceExtent = 50.0;

  /// The scale of a map whose outline (an area's hull, a path's points) is `outline`: its
  /// bounding box's larger side.
  explicit MarkerScale(const core::Ring& outline);

  /// A size (line width, sphere diameter; m) of `base` on a map of kReferenceExtent.
  double size(double base) const { return base * factor_; }

  /// Every how many vertices rings of `ring_points` vertices in all are drawn so that they
  /// take at most `budget` points (1: every vertex).
  static std::size_t stride(std::size_t ring_points, std::size_t budget);

  /// The points of every marker of `markers`: each point of a list or strip, one for a single
  /// shape (sphere, cube, text); none for a deletion.
  static std::size_t pointCount(const visualization_msgs::MarkerArray& markers);

 private:
  double factor_ = 1.0;
};

}  // namespace kinematic_coverage::nodes
