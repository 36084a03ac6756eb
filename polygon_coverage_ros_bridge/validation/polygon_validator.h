#pragma once

#include <cstddef>
#include <string>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// Size limits of the input the package accepts (docs/REFERENCE.md, Geometry and input
/// rules: inputs over them are invalid input). They keep the exact-arithmetic
/// cleaning and the planner within seconds and bounded memory.
/// At most this many vertices in the hull and all holes together.
constexpr std::size_t kMaxTotalVertices = 100000;
/// At most this many holes.
constexpr std::size_t kMaxHoles = 5000;
/// Largest absolute value of a coordinate, metres (UTM northings stay below 1e7 m).
constexpr double kMaxCoordinateMagnitude = 1e8;

/// Checks raw input polygons before cleaning (docs/REFERENCE.md, Geometry and input rules),
/// with exact predicates (CGAL's Exact_predicates_inexact_constructions_kernel), and throws
/// InvalidInputError naming the first problem: which ring ("hull", "hole 2"; holes are
/// numbered from 0 in input order, as `polygon.holes[2]` in a mission file), which vertex
/// (numbered from 0 in input order) or which pair of edges (edge i joins vertex i to the
/// next one).
class PolygonValidator {
 public:
  /// Rejects: more than the size limits above; a non-finite or too large coordinate; a
  /// ring with fewer than 3 distinct vertices or zero area, or a sliver (a mean width,
  /// twice the area over the perimeter, of at most 1e-9 of the ring's scale: its extent or
  /// its largest coordinate); a
  /// self-intersecting ring
  /// (checked after dropping duplicate consecutive vertices, so a repeated vertex is
  /// allowed); a hole entirely outside the hull (their interiors do not meet).
  void validate(const PolygonWithHoles& polygon) const;

  /// Rejects a non-finite or too large start or goal, or one strictly inside a hole of
  /// `polygon` (the raw polygon, so that the hole is named as in the input), e.g.
  /// "start (5, 5) lies inside hole 2". `name` is "start" or "goal". Outside the hull is
  /// allowed: the planner joins such a point by a straight leg.
  void validateEndpoint(const std::string& name, const Point2& point,
                        const PolygonWithHoles& polygon) const;

  /// Throws InvalidInputError when `ring` (duplicate consecutive vertices allowed) is not a
  /// simple polygon with non-zero area, or is a sliver (above); `ring_name` names it in the
  /// message. Used on the cleaner's output as well.
  void validateRing(const Ring& ring, const std::string& ring_name) const;
};

}  // namespace kinematic_coverage::core
