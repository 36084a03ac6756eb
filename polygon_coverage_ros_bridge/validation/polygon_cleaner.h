#pragma once

#include <string>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// The free area made from a raw polygon, and one line per cleaning step applied.
struct CleanedPolygon {
  /// Counter-clockwise hull, clockwise holes, every ring simple, no two rings crossing
  /// (a hole may touch the hull or another hole at single points).
  PolygonWithHoles free_area;
  /// One warning per cleaning step applied, e.g. "hole 3 and hole 5 overlap: merged".
  std::vector<std::string> warnings;
};

/// Cleans an input polygon (docs/REFERENCE.md, Geometry and input rules) with exact
/// Boolean operations (CGAL's Exact_predicates_exact_constructions_kernel): duplicate
/// consecutive vertices are dropped; holes that overlap or touch each other along an edge
/// (or at several points, or one inside the other) are merged; the parts of holes outside
/// the hull are cut off, and a hole crossing or touching the hull along an edge cuts the
/// hull back. Holes are named as in PolygonValidator ("hole 2" is the input's third hole).
class PolygonCleaner {
 public:
  /// Cleans `raw`, which must have passed PolygonValidator::validate. Throws
  /// InvalidInputError when the holes cover the whole hull or split the free area into
  /// several disconnected parts (parts meeting at single points count as disconnected).
  CleanedPolygon clean(const PolygonWithHoles& raw) const;
};

}  // namespace kinematic_coverage::core
