#include "polygon_coverage_ros_bridge/geometry/region_intersection.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>

#include <cmath>
#include <iterator>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using CgalPolygon = CGAL::Polygon_2<Kernel>;
using CgalPolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;
using CgalPolygonSet = CGAL::Polygon_set_2<Kernel>;

CgalPolygon toCgal(const Ring& ring, bool counter_clockwise) {
  CgalPolygon polygon;
  for (const Point2& p : ring) {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y())) {
      throw InvalidInputError("region intersection: a vertex has a non-finite coordinate");
    }
    if (!polygon.is_empty() && polygon.container().back() == Kernel::Point_2(p.x(), p.y())) {
      continue;
    }
    polygon.push_back(Kernel::Point_2(p.x(), p.y()));
  }
  if (polygon.size() >= 3 && polygon.is_simple() &&
      polygon.is_counterclockwise_oriented() != counter_clockwise) {
    polygon.reverse_orientation();
  }
  return polygon;
}

CgalPolygonWithHoles toCgal(const PolygonWithHoles& polygon) {
  CgalPolygonWithHoles cgal(toCgal(polygon.hull, true));
  for (const Ring& hole : polygon.holes) cgal.add_hole(toCgal(hole, false));
  return cgal;
}

CgalPolygonSet toSet(const PolygonWithHoles& polygon) {
  CgalPolygonSet set;
  set.insert(toCgal(polygon));
  return set;
}

Ring fromCgal(const CgalPolygon& polygon) {
  Ring ring;
  for (auto it = polygon.vertices_begin(); it != polygon.vertices_end(); ++it) {
    ring.emplace_back(CGAL::to_double(it->x()), CGAL::to_double(it->y()));
  }
  return ring;
}

/// The bounded polygons of a set, rounded to doubles; parts below `min_area` left out.
std::vector<PolygonWithHoles> toPolygons(const CgalPolygonSet& set, double min_area) {
  std::vector<CgalPolygonWithHoles> parts;
  set.polygons_with_holes(std::back_inserter(parts));
  std::vector<PolygonWithHoles> result;
  for (const CgalPolygonWithHoles& part : parts) {
    if (part.is_unbounded()) continue;
    PolygonWithHoles polygon{fromCgal(part.outer_boundary()), {}};
    for (auto it = part.holes_begin(); it != part.holes_end(); ++it) {
      polygon.holes.push_back(fromCgal(*it));
    }
    if (kinematic_coverage::core::area(polygon) < min_area) continue;
    result.push_back(std::move(polygon));
  }
  return result;
}

}  // namespace

std::vector<PolygonWithHoles> intersectWithRegions(const PolygonWithHoles& area,
                                                   const std::vector<PolygonWithHoles>& regions,
                                                   double min_area) {
  CgalPolygonSet covered;
  for (const PolygonWithHoles& region : regions) covered.join(toSet(region));
  covered.intersection(toSet(area));
  return toPolygons(covered, min_area);
}

std::vector<PolygonWithHoles> unionOfAreas(const std::vector<PolygonWithHoles>& areas) {
  // One aggregated union (divide and conquer over the areas) instead of one join per area,
  // each over the growing union: hundreds of parts and corridors of a chart.
  std::vector<CgalPolygonWithHoles> polygons;
  for (const PolygonWithHoles& area : areas) polygons.push_back(toCgal(area));
  CgalPolygonSet united;
  united.join(polygons.begin(), polygons.end());
  return toPolygons(united, 0.0);
}

}  // namespace kinematic_coverage::core
