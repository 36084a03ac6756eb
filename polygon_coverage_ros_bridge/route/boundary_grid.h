#pragma once

#include <vector>

#include "polygon_coverage_ros_bridge/geometry/edge_grid.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// The boundary of a polygon with holes, its edges bucketed in a uniform grid, answering
/// fast whether a straight segment stays inside the closed polygon: the visibility test
/// of the transition router (shortest paths in the offset free area).
///
/// Boundary points count as inside within tolerance(). A segment may run along an edge
/// and may pass through a vertex, also a pinch point where rings touch, as long as it
/// goes from free area to free area there: at each vertex the test looks at the rays of
/// all edges meeting there and asks on which side of them the segment's directions lie.
class BoundaryGrid {
 public:
  /// Where a point touches the boundary, for the local test at a segment's end.
  struct Contact {
    int cluster = -1;        ///< the vertex whose rays judge directions at p (see contactOf), or -1
    std::vector<int> edges;  ///< the edges within tolerance (none when a vertex is)
  };

  /// Takes the hull and holes in either orientation (they are made CCW and CW) and drops
  /// repeated consecutive vertices. Throws InvalidInputError for a non-finite
  /// coordinate or a ring with fewer than 3 distinct vertices or zero area.
  explicit BoundaryGrid(const PolygonWithHoles& polygon);

  /// The polygon as tested: CCW hull, CW holes, no repeated vertices.
  const PolygonWithHoles& polygon() const { return polygon_; }

  /// The distance within which a point counts as on the boundary: a fixed fraction of
  /// the map's extent, so that the test behaves the same at every map scale.
  double tolerance() const { return tolerance_; }

  /// True when p lies in the closed polygon, within tolerance().
  bool contains(const Point2& p) const;

  /// The vertex or edges that p touches (empty for a point off the boundary). A point
  /// within tolerance of two edges that meet at a vertex with wall in the narrow angle
  /// between them lies on that wall's sliver: the vertex judges its directions, and the
  /// edges stay in the contact.
  Contact contactOf(const Point2& p) const;

  /// True when the closed segment [a, b] lies in the closed polygon, for ends inside it.
  bool segmentInside(const Point2& a, const Point2& b) const;

  /// segmentInside with the ends' contacts known (contactOf), for repeated queries.
  bool segmentInside(const Point2& a, const Contact& a_contact, const Point2& b,
                     const Contact& b_contact) const;

  /// The vertices that a shortest path may have to bend at: reflex corners of the free
  /// area, pinch points (several corners at one position) and vertices lying on another
  /// ring's edge. Returned as vertex clusters.
  std::vector<int> bendClusters() const;

  /// True when the cluster is one corner (two edges, one wedge of wall) and the ray from it
  /// along `direction` (its length that of the segment it stands for) starts into that wall,
  /// clear of both edges' rays by more than the tolerance over that length. False at pinch
  /// points, where a route may pass between walls.
  bool runsIntoCorner(int cluster, const Point2& direction) const;

  /// The position of a vertex cluster (the coinciding vertices' first occurrence).
  const Point2& clusterPosition(int cluster) const { return clusters_[cluster].position; }

 private:
  /// Vertices of the rings closer than tolerance() are one cluster; its rays are the
  /// directions of the edges leaving it, each tagged with the side the free area is on.
  struct Cluster {
    Point2 position;
    std::vector<double> ray_angles;
    std::vector<char> ray_outgoing;  ///< free area counter-clockwise of the ray
    bool bend = false;
  };

  void buildClusters();
  void buildGrid();
  void addTouchingEdges();
  bool directionFree(int cluster, const Point2& direction, double angle_tolerance) const;
  bool touches(const Contact& contact, int edge) const;
  /// True when the cluster is one convex corner (free angle under 180 degrees) and both
  /// ends of [a, b] lie in its free wedge, up to the tolerance: the segment is then inside
  /// the area near the corner, whatever angles it makes with the corner's rays (a chord
  /// between its edges).
  bool passesInsideConvexCorner(int cluster, const Point2& a, const Point2& b) const;
  /// The vertex cluster where edges e and f meet with wall in the narrow angle between
  /// them, or -1.
  int wallCornerBetween(int e, int f) const;
  /// True when the segment from an end touching `contact` to `far_end` starts into the
  /// free side there (at a vertex contact: the segment from the vertex itself, which may
  /// deviate from a ray by the tolerance over its length).
  bool endAllows(const Contact& contact, const Point2& far_end) const;

  PolygonWithHoles polygon_;
  double tolerance_ = 0.0;
  std::vector<Point2> edge_start_;
  std::vector<Point2> edge_end_;
  std::vector<int> start_cluster_;
  std::vector<int> end_cluster_;
  std::vector<int> edge_ring_;  ///< 0 for the hull's edges, h + 1 for hole h's
  std::vector<Cluster> clusters_;
  EdgeGrid grid_;
};

}  // namespace kinematic_coverage::core
