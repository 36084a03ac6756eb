#pragma once

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// The polygon with fewer vertices: every vertex whose removal moves the boundary by at
/// most `tolerance` goes, without ever making a ring cross itself or another ring
/// (CGAL's topology-preserving polyline simplification over a constrained
/// triangulation). The thesis's footprint-based remaining areas carry thousands of
/// staircase vertices (its section 3.4); this keeps the shape and drops them. Rings keep
/// their orientation. Throws InvalidInputError for a negative or non-finite tolerance.
PolygonWithHoles simplifyPolygon(const PolygonWithHoles& polygon, double tolerance);

}  // namespace kinematic_coverage::core
