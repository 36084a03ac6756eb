#include "polygon_coverage_ros_bridge/validation/polygon_validator.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/box_intersection_d.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using KPoint = Kernel::Point_2;
using KSegment = Kernel::Segment_2;
using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPolygon = CGAL::Polygon_2<ExactKernel>;
using EdgeBox = CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t>;

/// A ring whose mean width (twice its area over its perimeter) is at most this share of
/// the ring's scale (its extent or largest coordinate) is a sliver: the route stage treats
/// points that close as one (its tolerance, route/boundary_grid.cpp), so such a ring is a line to
/// the planner.
constexpr double kRelativeSliverWidth = 1e-9;

/// Rejects a ring thinner than `tolerance` on average (see kRelativeSliverWidth).
void checkNotSliver(const Ring& ring, const std::string& ring_name, double tolerance) {
  double twice_area = 0.0;
  double perimeter = 0.0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    // Relative to the first vertex, so that large coordinates do not cancel.
    const Point2 a = ring[i] - ring.front();
    const Point2 b = ring[(i + 1) % n] - ring.front();
    twice_area += a.x() * b.y() - b.x() * a.y();
    perimeter += (b - a).norm();
  }
  if (std::abs(twice_area) <= tolerance * perimeter) {
    throw InvalidInputError(ring_name + " is a sliver: its mean width (twice its area, " +
                            formatNumber(0.5 * std::abs(twice_area)) +
                            " m^2, over its perimeter, " + formatNumber(perimeter) +
                            " m) is below " + formatNumber(tolerance) +
                            " m (1e-9 of its scale), which the planner cannot tell "
                            "from a line");
  }
}

/// A ring without duplicate consecutive vertices, remembering each vertex's input index.
struct DedupedRing {
  std::vector<KPoint> points;
  std::vector<std::size_t> input_index;
};

DedupedRing dropDuplicateVertices(const Ring& ring) {
  DedupedRing result;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const KPoint p(ring[i].x(), ring[i].y());
    if (!result.points.empty() && result.points.back() == p) continue;
    result.points.push_back(p);
    result.input_index.push_back(i);
  }
  while (result.points.size() > 1 && result.points.back() == result.points.front()) {
    result.points.pop_back();
    result.input_index.pop_back();
  }
  return result;
}

void checkCoordinates(const Point2& point, const std::string& where) {
  for (int axis = 0; axis < 2; ++axis) {
    const double value = point[axis];
    const char* name = axis == 0 ? "x" : "y";
    if (!std::isfinite(value)) {
      throw InvalidInputError(where + ": the " + name + " coordinate " + formatNumber(value) +
                              " is not finite");
    }
    if (std::abs(value) > kMaxCoordinateMagnitude) {
      throw InvalidInputError(where + ": the " + name + " coordinate " + formatNumber(value) +
                              " exceeds the limit of +-" + formatNumber(kMaxCoordinateMagnitude) +
                              " m");
    }
  }
}

std::string edgeName(const DedupedRing& ring, std::size_t edge) {
  const std::size_t from = ring.input_index[edge];
  const std::size_t to = ring.input_index[(edge + 1) % ring.points.size()];
  return "edge " + std::to_string(from) + " (vertices " + std::to_string(from) + "-" +
         std::to_string(to) + ")";
}

Point2 toPoint2(const KPoint& p) { return {p.x(), p.y()}; }

/// The message for two non-adjacent edges i < j of `ring` that intersect.
std::string describeIntersection(const DedupedRing& ring, std::size_t i, std::size_t j) {
  const std::size_t n = ring.points.size();
  const KSegment a(ring.points[i], ring.points[(i + 1) % n]);
  const KSegment b(ring.points[j], ring.points[(j + 1) % n]);
  const auto result = CGAL::intersection(a, b);
  if (result) {
    if (const KSegment* overlap = boost::get<KSegment>(&*result)) {
      return edgeName(ring, i) + " and " + edgeName(ring, j) + " overlap from " +
             formatPoint(toPoint2(overlap->source())) + " to " +
             formatPoint(toPoint2(overlap->target()));
    }
    if (const KPoint* p = boost::get<KPoint>(&*result)) {
      for (std::size_t u : {i, (i + 1) % n}) {
        for (std::size_t v : {j, (j + 1) % n}) {
          if (ring.points[u] == ring.points[v]) {
            return "vertices " + std::to_string(ring.input_index[u]) + " and " +
                   std::to_string(ring.input_index[v]) + " coincide at " +
                   formatPoint(toPoint2(*p));
          }
        }
      }
      return edgeName(ring, i) + " and " + edgeName(ring, j) + " meet at " +
             formatPoint(toPoint2(*p));
    }
  }
  return edgeName(ring, i) + " and " + edgeName(ring, j) + " intersect";
}

/// The first (lowest-numbered) pair of intersecting edges of a non-simple ring, as a
/// message; adjacent edges count when they fold back onto each other.
std::string findSelfIntersection(const DedupedRing& ring) {
  const std::size_t n = ring.points.size();
  for (std::size_t k = 0; k < n; ++k) {
    const KPoint& a = ring.points[(k + n - 1) % n];
    const KPoint& b = ring.points[k];
    const KPoint& c = ring.points[(k + 1) % n];
    if (CGAL::collinear(a, b, c) && CGAL::angle(a, b, c) == CGAL::ACUTE) {
      return "its edges fold back onto each other at vertex " +
             std::to_string(ring.input_index[k]) + " " + formatPoint(toPoint2(b));
    }
  }
  std::vector<EdgeBox> boxes;
  boxes.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    boxes.emplace_back(ring.points[k].bbox() + ring.points[(k + 1) % n].bbox(), k);
  }
  std::optional<std::pair<std::size_t, std::size_t>> first;
  auto report = [&](const EdgeBox& box_a, const EdgeBox& box_b) {
    std::size_t i = std::min(box_a.info(), box_b.info());
    std::size_t j = std::max(box_a.info(), box_b.info());
    if (j == i + 1 || (i == 0 && j == n - 1)) return;
    const KSegment a(ring.points[i], ring.points[(i + 1) % n]);
    const KSegment b(ring.points[j], ring.points[(j + 1) % n]);
    if (!CGAL::do_intersect(a, b)) return;
    if (!first || std::make_pair(i, j) < *first) first = std::make_pair(i, j);
  };
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), report, std::ptrdiff_t(10),
                                CGAL::Box_intersection_d::CLOSED);
  if (!first) return "its edges intersect";
  return describeIntersection(ring, first->first, first->second);
}

ExactPolygon toExactPolygon(const DedupedRing& ring) {
  ExactPolygon polygon;
  for (const KPoint& p : ring.points) polygon.push_back(ExactKernel::Point_2(p.x(), p.y()));
  if (polygon.is_clockwise_oriented()) polygon.reverse_orientation();
  return polygon;
}

std::string ringName(std::size_t hole) { return "hole " + std::to_string(hole); }

}  // namespace

void PolygonValidator::validateRing(const Ring& ring, const std::string& ring_name) const {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    checkCoordinates(ring[i], ring_name + " vertex " + std::to_string(i));
  }
  const DedupedRing deduped = dropDuplicateVertices(ring);
  if (deduped.points.size() < 3) {
    throw InvalidInputError(ring_name + " has " + std::to_string(deduped.points.size()) +
                            " distinct vertices: a ring needs at least 3");
  }
  const KPoint& first = deduped.points[0];
  const auto second = std::find_if(deduped.points.begin(), deduped.points.end(),
                                   [&](const KPoint& p) { return p != first; });
  const bool zero_area =
      std::all_of(deduped.points.begin(), deduped.points.end(),
                  [&](const KPoint& p) { return CGAL::collinear(first, *second, p); });
  if (zero_area) {
    throw InvalidInputError(ring_name + " has zero area: all its vertices lie on one line");
  }
  if (!CGAL::is_simple_2(deduped.points.begin(), deduped.points.end(), Kernel())) {
    throw InvalidInputError(ring_name + " is self-intersecting: " + findSelfIntersection(deduped));
  }
  Eigen::AlignedBox2d extent;
  for (const Point2& p : ring) extent.extend(p);
  checkNotSliver(ring, ring_name,
                 kRelativeSliverWidth *
                     std::max({1.0, extent.sizes().maxCoeff(), extent.min().cwiseAbs().maxCoeff(),
                               extent.max().cwiseAbs().maxCoeff()}));
}

void PolygonValidator::validate(const PolygonWithHoles& polygon) const {
  if (polygon.holes.size() > kMaxHoles) {
    throw InvalidInputError("the polygon has " + std::to_string(polygon.holes.size()) +
                            " holes, more than the limit of " + std::to_string(kMaxHoles));
  }
  std::size_t total_vertices = polygon.hull.size();
  for (const Ring& hole : polygon.holes) total_vertices += hole.size();
  if (total_vertices > kMaxTotalVertices) {
    throw InvalidInputError("the polygon has " + std::to_string(total_vertices) +
                            " vertices in total, more than the limit of " +
                            std::to_string(kMaxTotalVertices));
  }
  validateRing(polygon.hull, "hull");
  for (std::size_t h = 0; h < polygon.holes.size(); ++h) {
    validateRing(polygon.holes[h], ringName(h));
  }
  // A hole entirely outside the hull: their interiors do not meet. A hole vertex strictly
  // inside the hull settles it cheaply; otherwise an exact Boolean test decides.
  const DedupedRing hull = dropDuplicateVertices(polygon.hull);
  const CGAL::Bbox_2 hull_box = CGAL::bbox_2(hull.points.begin(), hull.points.end());
  std::optional<ExactPolygon> exact_hull;
  for (std::size_t h = 0; h < polygon.holes.size(); ++h) {
    const DedupedRing hole = dropDuplicateVertices(polygon.holes[h]);
    const CGAL::Bbox_2 hole_box = CGAL::bbox_2(hole.points.begin(), hole.points.end());
    bool meets = CGAL::do_overlap(hull_box, hole_box);
    if (meets) {
      const bool vertex_inside =
          CGAL::bounded_side_2(hull.points.begin(), hull.points.end(), hole.points.front(),
                               Kernel()) == CGAL::ON_BOUNDED_SIDE;
      if (!vertex_inside) {
        if (!exact_hull) exact_hull = toExactPolygon(hull);
        meets = CGAL::do_intersect(*exact_hull, toExactPolygon(hole), CGAL::Tag_false());
      }
    }
    if (!meets) {
      throw InvalidInputError(ringName(h) + " lies entirely outside the hull");
    }
  }
}

void PolygonValidator::validateEndpoint(const std::string& name, const Point2& point,
                                        const PolygonWithHoles& polygon) const {
  checkCoordinates(point, name + " " + formatPoint(point));
  const KPoint p(point.x(), point.y());
  for (std::size_t h = 0; h < polygon.holes.size(); ++h) {
    const DedupedRing hole = dropDuplicateVertices(polygon.holes[h]);
    if (hole.points.size() < 3) continue;
    const CGAL::Bbox_2 box = CGAL::bbox_2(hole.points.begin(), hole.points.end());
    if (!CGAL::do_overlap(box, p.bbox())) continue;
    if (CGAL::bounded_side_2(hole.points.begin(), hole.points.end(), p, Kernel()) ==
        CGAL::ON_BOUNDED_SIDE) {
      throw InvalidInputError(name + " " + formatPoint(point) + " lies inside " + ringName(h));
    }
  }
}

}  // namespace kinematic_coverage::core
