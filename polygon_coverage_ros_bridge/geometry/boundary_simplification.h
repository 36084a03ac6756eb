#pragma once

#include <cstddef>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// Drops boundary noise that a footprint cannot tell from a straight wall, so that cells
/// and route nodes follow the topology of an area, not its noise: the boundary is
/// simplified inward only (the hull shrinks, holes grow), so that the simplified area lies
/// inside the given one and nothing planned in it comes nearer a wall than the given area
/// allows. Its vertices are a subset of the given ones; every given vertex lies within the
/// tolerance of the simplified boundary (so every point of either boundary lies within the
/// tolerance of the other); no ring is dropped or loses its area; and the rings stay
/// simple and apart (a vertex is dropped only when the triangle it cuts off holds no other
/// vertex of any ring, which no edge can then cross).
class BoundarySimplification {
 public:
  /// `tolerance` (m, >= 0 and finite): how far the boundary may move. Throws
  /// InvalidInputError otherwise.
  explicit BoundarySimplification(double tolerance);

  /// The simplified area (rings in the given orientations) of a valid polygon with holes
  /// (simple rings, holes inside the hull and apart; touching at points allowed).
  PolygonWithHoles simplify(const PolygonWithHoles& area) const;

  /// The number of vertices of the hull and the holes together.
  static std::size_t vertexCount(const PolygonWithHoles& area);

 private:
  double tolerance_;
};

}  // namespace kinematic_coverage::core
