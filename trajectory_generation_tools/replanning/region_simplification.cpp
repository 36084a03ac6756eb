#include "trajectory_generation_tools/replanning/region_simplification.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/Polyline_simplification_2/simplify.h>

#include <cmath>
#include <cstdint>
#include <cstring>

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

/// A number in [0, 1) that depends on `p` alone (splitmix64 of its coordinates' bits).
double tieBreak(const Kernel::Point_2& p) {
  const auto mix = [](std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  };
  const double x = p.x();
  const double y = p.y();
  std::uint64_t x_bits = 0;
  std::uint64_t y_bits = 0;
  std::memcpy(&x_bits, &x, sizeof x);
  std::memcpy(&y_bits, &y, sizeof y);
  return static_cast<double>(mix(x_bits ^ mix(y_bits)) >> 11) * 0x1.0p-53;
}

/// CGAL's squared-distance cost plus a tie-break far below the tolerance. CGAL orders its
/// constraints by their addresses in memory, so among vertices of equal cost (the many
/// collinear vertices of a raster contour) the one removed first, and so the result, would
/// depend on the heap's layout; with a tie-break from each vertex's own position the same
/// polygon always simplifies the same way.
class DeterministicSquaredDistanceCost {
 public:
  explicit DeterministicSquaredDistanceCost(double tolerance)
      : tie_scale_(kTieBreakShare * tolerance * tolerance) {}

  template <class CDT>
  boost::optional<typename CDT::Geom_traits::FT> operator()(
      const CGAL::Constrained_triangulation_plus_2<CDT>& triangulation,
      typename CGAL::Constrained_triangulation_plus_2<CDT>::Vertices_in_constraint_iterator vertex)
      const {
    const auto cost = PS::Squared_distance_cost()(triangulation, vertex);
    if (!cost) return cost;
    return *cost + tie_scale_ * tieBreak((*vertex)->point());
  }

 private:
  /// The tie-break's largest share of the squared tolerance.
  static constexpr double kTieBreakShare = 1e-9;
  double tie_scale_;
};

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
  const CgalPolygonWithHoles simplified =
      PS::simplify(input, DeterministicSquaredDistanceCost(tolerance),
                   PS::Stop_above_cost_threshold(tolerance * tolerance));
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
