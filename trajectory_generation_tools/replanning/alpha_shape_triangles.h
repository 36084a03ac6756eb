#pragma once

#include <array>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// The interior triangles of the regularized alpha shape of `points` (CGAL Alpha_shape_2
/// with squared radius alpha^2): the concave hull of the thesis's section 3.4, as
/// triangles rather than a boundary polygon, so that it never has to be a simple polygon
/// (the failure of its Fig. 3.12). Fewer than 3 points give none. Throws InvalidInputError
/// for an alpha that is not positive and finite or a non-finite point.
std::vector<std::array<Point2, 3>> alphaShapeTriangles(const std::vector<Point2>& points,
                                                       double alpha);

}  // namespace kinematic_coverage::core
