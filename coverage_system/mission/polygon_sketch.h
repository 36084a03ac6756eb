#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// A polygon with holes while an operator draws it vertex by vertex (the rviz tool
/// kinematic_coverage/DrawPolygon): the closed rings, the hull first and then the holes, and at
/// most one open ring being drawn. The rings keep their vertices as clicked (order and
/// orientation); whether they are an acceptable polygon is PolygonValidator's answer, so the
/// drawing is rejected exactly when the planner would reject it, with the same message.
class PolygonSketch {
 public:
  /// The ring a vertex belongs to.
  enum class RingKind { kHull, kHole, kOpen };

  /// A vertex of the sketch: its ring (`hole` numbers the holes from 0, as the validator's
  /// messages do; unused for the others) and its index in that ring.
  struct VertexId {
    RingKind ring = RingKind::kOpen;
    std::size_t hole = 0;
    std::size_t index = 0;
  };

  /// Appends `point` to the open ring, starting one when no ring is open.
  void addVertex(const Point2& point);

  /// Closes the open ring: it becomes the hull when there is none, else the next hole.
  /// Returns false, changing nothing, when the open ring has fewer than 3 vertices.
  bool closeRing();

  /// Drops the open ring; the closed rings stay.
  void cancelOpenRing();

  /// Moves an existing vertex (std::out_of_range for one that does not exist).
  void moveVertex(const VertexId& vertex, const Point2& point);

  /// Deletes an existing vertex (std::out_of_range for one that does not exist). A closed ring
  /// left with fewer than 3 vertices is removed: a removed hole renumbers the later holes; a
  /// removed hull leaves the holes, and the next ring closed becomes the hull.
  void deleteVertex(const VertexId& vertex);

  /// The vertex nearest to `point` no farther than `tolerance` (metres), or none. Of vertices
  /// at the same distance the hull's comes first, then the holes' in order, then the open
  /// ring's.
  std::optional<VertexId> nearestVertex(const Point2& point, double tolerance) const;

  /// The position of an existing vertex (std::out_of_range for one that does not exist).
  const Point2& vertex(const VertexId& vertex) const;

  /// Whether a hull is closed.
  bool hasHull() const { return !hull_.empty(); }
  /// The closed hull (empty while none is closed).
  const Ring& hull() const { return hull_; }
  /// The closed holes.
  const std::vector<Ring>& holes() const { return holes_; }
  /// The ring being drawn (empty when none is open).
  const Ring& openRing() const { return open_; }

  /// Why the closed rings are not a valid polygon: PolygonValidator's message naming the ring,
  /// vertex or edges, or that no hull is closed yet; nothing when they are valid. The open ring
  /// is not part of it.
  std::optional<std::string> validity() const;

  /// The polygon to publish: the closed rings when no ring is open and they are valid;
  /// nothing otherwise.
  std::optional<PolygonWithHoles> completePolygon() const;

 private:
  Ring& ring(const VertexId& vertex);
  const Ring& ring(const VertexId& vertex) const;

  Ring hull_;
  std::vector<Ring> holes_;
  Ring open_;
};

}  // namespace kinematic_coverage::core
