#pragma once

#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"

namespace kinematic_coverage::core {

/// One way to sweep a cell: lanes parallel to `direction`, visited in order, joined at
/// alternating ends (boustrophedon).
struct SweepPattern {
  std::vector<Point2> path;  ///< lane ends and the bends of the joins between lanes
  double direction = 0.0;
  const Point2& start() const { return path.front(); }
  const Point2& end() const { return path.back(); }
};

/// A path between two points through the area being planned (both ends included).
using TransitionPath = std::function<std::vector<Point2>(const Point2&, const Point2&)>;

/// Places the lanes of a cell and builds its four sweep patterns per direction (both
/// lane orders, both first-lane directions).
///
/// Lanes run parallel to the direction, as few as possible: at most one sweep distance
/// s = (1 - overlap) W apart, the outermost within min(s/2, W/2 - L/2) of the cell's sides
/// (so that the footprint also reaches half a footprint length beyond a wall); the outer
/// lanes sit at that margin unless neighbours would then be closer than half a sweep
/// distance, in which case the lanes are spread evenly. Where a corner of the cell would
/// stay unseen by every lane's swept footprint, an extra lane is placed through it. The
/// lanes' flanks (the sides within 15 degrees of the direction) are then checked along the
/// lanes' whole extent (soak seed 3640): a point of a flank that lies alongside one of its two
/// neighbouring lanes (between that lane's ends) must lie in some lane's swept footprint;
/// where a flank slants away from the lanes and leaves such points unseen, a lane is moved
/// or one is added until every such point is seen. A corner moves a lane only when that
/// leaves no more of the flanks unseen. Lane ends stop `lane_end_inset` short of the
/// cell's boundary: where the walls are closer than half a footprint length
/// (wall_distance < L/2), the footprint still reaches the whole reachable band from
/// max(0, L/2 - wall_distance) inside.
class SweepPatternGenerator {
 public:
  explicit SweepPatternGenerator(const FrustumSensor& sensor, double lane_end_inset = 0.0)
      : sensor_(sensor), lane_end_inset_(lane_end_inset) {}

  /// As above; only corners that are vertices of `area` (the decomposed area) get extra
  /// lanes, and only the parts of a cell's sides that lie on the area's boundary are
  /// checked, except within W/2 - margin of a decomposition cut: a cut lies on the
  /// neighbouring cell's side, and that cell's lanes, within the margin of it, see that
  /// far across it. Lane ends within 1e-8 of the map's scale of the area's boundary are
  /// put on it, so that the router locates them exactly.
  SweepPatternGenerator(const FrustumSensor& sensor, double lane_end_inset,
                        const PolygonWithHoles& area);

  /// As above for the cells of `area`, a simplification of `exact_area` (BoundarySimplification:
  /// a subset of its vertices, the boundary moved inward; with every vertex kept, `area` is
  /// exact and swept as above): a lane end on the area's boundary goes on along the lane to
  /// the exact area's boundary, at most one sweep distance (then in by the lane-end inset), so
  /// that lanes see up to the exact walls that the simplified boundary cut off. The outermost
  /// lanes keep their margin from the simplified sides, up to the simplification's tolerance
  /// farther from the exact ones (taking it off the margin added lanes to every cell where
  /// W/2 - L/2 bounds the margin: up to 8 % time cost on trapezoidal shorelines); the
  /// planner's coverage repair sees what that leaves unseen.
  SweepPatternGenerator(const FrustumSensor& sensor, double lane_end_inset,
                        const PolygonWithHoles& area, const PolygonWithHoles& exact_area);

  /// The inset that keeps the reachable band seen (see the class comment).
  static double laneEndInset(const FrustumSensor& sensor, double wall_distance);

  /// The lanes of `cell` (counter-clockwise, monotone for `direction`), each as its two
  /// ends, in order across the direction; the first end has the smaller coordinate along it.
  std::vector<std::pair<Point2, Point2>> lanes(const Ring& cell, double direction) const;

  /// Sweep patterns per cell and lane direction (both lane orders, both first-lane
  /// directions): the planner's generalized TSP has this many nodes per kept direction.
  static constexpr std::size_t kPatternsPerDirection = 4;

  /// The four patterns of the cell for one direction. `transition` joins two lane ends
  /// when the straight join would leave the cell.
  std::vector<SweepPattern> patterns(const Ring& cell, double direction,
                                     const TransitionPath& transition) const;

 private:
  /// True when the corner may need an extra lane (see the constructors).
  bool isAreaVertex(const Point2& corner) const;
  /// The lanes at `positions` (sweep frame) with vertical extents `spans` in the cell, as
  /// segments in the world frame: their ends pulled in by the lane-end inset and kept in
  /// the cell and on the area's boundary where they are within rounding of it.
  std::vector<std::pair<Point2, Point2>> laneEnds(
      const Ring& cell, double direction, const std::vector<double>& positions,
      const std::vector<std::pair<double, double>>& spans, double scale) const;

  /// The parts of the cell's edges that lie on the area's boundary (every edge without an
  /// area), less the points within `cut_reach` of the parts that are decomposition cuts.
  std::vector<std::pair<Point2, Point2>> sidesToSee(const Ring& cell, double cut_reach) const;

  /// The nearest point of the area's boundary when one lies within `reach` of p, else p.
  Point2 onNearbyAreaBoundary(const Point2& p, double reach) const;

  /// How far a lane end at `end`, on the area's boundary, goes on in the direction `along`
  /// (unit) before it meets the exact area's boundary: 0 when it lies on that boundary, at
  /// most one sweep distance.
  double extensionToExactBoundary(const Point2& end, const Point2& along, double snap) const;

  /// The parameter intervals in [0, 1] of the edge a + t (b - a) that lie on area edges.
  std::vector<std::pair<double, double>> onAreaBoundary(const Point2& a, const Point2& b) const;

  FrustumSensor sensor_;
  double lane_end_inset_;
  std::vector<Point2> area_vertices_;                  ///< sorted by x; empty: every corner counts
  std::vector<std::pair<Point2, Point2>> area_edges_;  ///< sorted by their smaller x
  double widest_area_edge_ = 0.0;                      ///< largest x extent of an area edge
  /// The exact area's edges, sorted by their smaller x (empty: the area is exact).
  std::vector<std::pair<Point2, Point2>> exact_edges_;
  double widest_exact_edge_ = 0.0;
  double vertex_tolerance_ = 0.0;
};

}  // namespace kinematic_coverage::core
