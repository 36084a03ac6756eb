#pragma once

#include <vector>

#include "polygon_coverage_ros_bridge/geometry/edge_grid.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/path/path_primitive.h"

namespace kinematic_coverage::core {

/// Clearance (m) a smoothing's arcs and segments must keep from the raw hull and holes.
/// Decision: touching is a collision; a primitive is free only when every point of it is
/// more than this from every boundary edge (1e-9 m is far above double rounding of
/// coordinates up to 1e5 m and far below any physical clearance).
constexpr double kContactTolerance = 1e-9;

/// The edges of a free area (hull and holes: collisions are checked against the
/// raw rings) in a uniform grid, for fast collision and containment queries of path
/// primitives: a query only tests the edges registered in the cells its bounding box meets.
/// Distances are analytic in doubles; whether two segments cross uses CGAL's exact
/// orientation predicate. Immutable after construction, so concurrent queries are safe.
class BoundaryEdgeIndex {
 public:
  /// Indexes every edge of the hull and holes. An empty hull stands for the unbounded plane
  /// (only the holes are obstacles). Rings need not be closed explicitly. `clearance` (m,
  /// parameter smoothing_clearance) is the distance a clear primitive keeps from every
  /// edge; below kContactTolerance the contact tolerance applies. Throws InvalidInputError
  /// for a non-finite coordinate or a negative or non-finite clearance.
  explicit BoundaryEdgeIndex(const PolygonWithHoles& free_area, double clearance = 0.0);

  /// True when the closed segment [a, b] keeps clearance() from every edge (more than the
  /// contact tolerance for a clearance of 0; within kClearanceTolerance for a larger one).
  bool segmentClear(const Point2& a, const Point2& b) const;
  /// True when the arc keeps clearance() from every edge, as segmentClear.
  bool arcClear(const PathPrimitive& arc) const;
  /// Metres a clothoid's chords, which primitiveClear tests, may stray from it.
  static constexpr double kClothoidChordTolerance = 1e-5;

  /// segmentClear / arcClear by kind; a rotation is its point; a clothoid its chords.
  bool primitiveClear(const PathPrimitive& primitive) const;
  /// True when p lies in the free area (inside the hull, outside every hole). Points on an
  /// edge may go either way; callers first check clearance.
  bool inside(const Point2& p) const;

  /// Number of indexed edges.
  std::size_t edgeCount() const { return from_.size(); }

  /// m: the distance a clear primitive keeps from every edge (at least kContactTolerance).
  double clearance() const { return clearance_; }

 private:
  /// The edges registered in the cells of the box [low, high] grown by clearance(),
  /// so that edges just outside the box still count: sorted, distinct.
  void edgesNear(const Point2& low, const Point2& high, std::vector<int>* ids) const;

  std::vector<Point2> from_;  ///< edge i runs from from_[i] to to_[i]
  std::vector<Point2> to_;
  bool has_hull_ = false;
  double clearance_ = kContactTolerance;
  /// m: a primitive nearer an edge than this, or as near, is not clear.
  double blocking_distance_ = kContactTolerance;
  EdgeGrid grid_;
};

}  // namespace kinematic_coverage::core
