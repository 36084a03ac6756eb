#pragma once

#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// The parts of `area` that lie in any of `regions` (exact Boolean operations, results
/// rounded to doubles), each a polygon with a counter-clockwise hull and clockwise
/// holes; parts smaller than `min_area` square metres are left out. Replanning covers
/// only what is left to see: the offset free area intersected with the
/// remaining area. Throws InvalidInputError for non-finite coordinates.
std::vector<PolygonWithHoles> intersectWithRegions(const PolygonWithHoles& area,
                                                   const std::vector<PolygonWithHoles>& regions,
                                                   double min_area);

/// The union of `areas` (exact Boolean operations, results rounded to doubles), as
/// disjoint polygons with a counter-clockwise hull and clockwise holes: the offset free
/// area's parts joined by their transit corridors. Throws InvalidInputError for
/// non-finite coordinates.
std::vector<PolygonWithHoles> unionOfAreas(const std::vector<PolygonWithHoles>& areas);

}  // namespace kinematic_coverage::core
