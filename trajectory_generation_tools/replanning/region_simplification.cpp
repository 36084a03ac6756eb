#include "trajectory_generation_tools/replanning/region_simplification.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/Polyline_simplification_2/simplify.h>

#include <cmath>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalPolygon = CGAL::Polygon_2<Kernel>;
using CgalPolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;
namespace PS = CGAL::Polyline_simplification_2;

CgalPolygon toCgal(const Ring& ring) {
  CgalPolygon polygon;
  for (const Point2& p : ring) polygon.push_back(Kernel::Point_2(p.x(), p.y()));
  return polygon;
}

Ring fromCgal(const CgalPolygon& polygon) {
  Ring ring;
  for (auto it = polygon.vertices_begin(); it != polygon.vertices_end(); ++it) {
    ring.emplace_back(it->x(), it->y());
  }
  return ring;
}

}  // namespace

PolygonWithHoles simplifyPolygon(const PolygonWithHoles& polygon, double tolerance) {
  if (!std::isfinite(tolerance) || tolerance < 0.0) {
    throw InvalidInputError("polygon simplification: the tolerance must be >= 0 and finite");
  }
  if (tolerance == 0.0 || polygon.hull.size() < 4) return polygon;
  CgalPolygon hull = toCgal(polygon.hull);
  if (hull.is_clockwise_oriented()) hull.reverse_orientation();
  CgalPolygonWithHoles input(hull);
  for (const Ring& ring : polygon.holes) {
    CgalPolygon hole = toCgal(ring);
    if (hole.is_counterclockwise_oriented()) hole.reverse_orientation();
    input.add_hole(hole);
  }
  const CgalPolygonWithHoles simplified = PS::simplify(
      input, PS::Squared_distance_cost(), PS::Stop_above_cost_threshold(tolerance * tolerance));
  PolygonWithHoles result;
  result.hull = fromCgal(simplified.outer_boundary());
  for (auto it = simplified.holes_begin(); it != simplified.holes_end(); ++it) {
    Ring hole = fromCgal(*it);
    if (hole.size() >= 3 && std::abs(signedArea(hole)) > 0.0)
      result.holes.push_back(std::move(hole));
  }
  return result;
}

}  // namespace kinematic_coverage::core
