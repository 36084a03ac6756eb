#pragma once

#include <string>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// The offset free area (INTERFACE section 3) and what was dropped to get it.
struct OffsetFreeArea {
  PolygonWithHoles area;              ///< CCW hull, CW holes
  std::vector<std::string> warnings;  ///< one line per dropped part
};

/// Computes the points of a cleaned free area at least `wall_distance` from the hull and
/// from every hole, with mitred (straight-skeleton) offsets: the hull shrinks by its
/// interior skeleton, each hole grows by its exterior skeleton, and the grown holes are
/// subtracted from the shrunk hull with exact Boolean operations, so that holes growing
/// into each other or into the hull merge. When the result falls apart, the largest part
/// is kept and every other part is reported as dropped. Throws InvalidInputError when
/// nothing is left.
OffsetFreeArea computeOffsetFreeArea(const PolygonWithHoles& free_area, double wall_distance);

}  // namespace kinematic_coverage::core
