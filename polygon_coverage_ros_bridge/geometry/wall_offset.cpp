#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/create_offset_polygons_2.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <memory>
#include <sstream>
#include <string>

#include "polygon_coverage_ros_bridge/base/parallel_for.h"
#include "polygon_coverage_ros_bridge/geometry/internal_error.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

using InexactKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;
using InexactPolygon = CGAL::Polygon_2<InexactKernel>;
using ExactPolygon = CGAL::Polygon_2<ExactKernel>;
using ExactPolygonWithHoles = CGAL::Polygon_with_holes_2<ExactKernel>;
using ExactPolygonSet = CGAL::Polygon_set_2<ExactKernel>;

/// Vertices closer than this are one vertex after conversion back to doubles.
constexpr double kDuplicateVertexTolerance = 1e-12;

InexactPolygon toInexactCcw(const Ring& ring) {
  InexactPolygon polygon;
  for (const Point2& p : ring) polygon.push_back(InexactKernel::Point_2(p.x(), p.y()));
  if (polygon.orientation() == CGAL::CLOCKWISE) polygon.reverse_orientation();
  return polygon;
}

ExactPolygon toExactCcw(const Ring& ring) {
  ExactPolygon polygon;
  for (const Point2& p : ring) polygon.push_back(ExactKernel::Point_2(p.x(), p.y()));
  if (polygon.orientation() == CGAL::CLOCKWISE) polygon.reverse_orientation();
  return polygon;
}

Ring toRing(const ExactPolygon& polygon, bool counter_clockwise) {
  Ring ring;
  for (auto it = polygon.vertices_begin(); it != polygon.vertices_end(); ++it) {
    const Point2 p(CGAL::to_double(it->x()), CGAL::to_double(it->y()));
    if (ring.empty() || (p - ring.back()).norm() > kDuplicateVertexTolerance) ring.push_back(p);
  }
  while (ring.size() > 1 && (ring.front() - ring.back()).norm() <= kDuplicateVertexTolerance) {
    ring.pop_back();
  }
  if ((signedArea(ring) > 0.0) != counter_clockwise) std::reverse(ring.begin(), ring.end());
  return ring;
}

double exactArea(const ExactPolygonWithHoles& polygon) {
  double result = std::abs(CGAL::to_double(polygon.outer_boundary().area()));
  for (auto it = polygon.holes_begin(); it != polygon.holes_end(); ++it) {
    result -= std::abs(CGAL::to_double(it->area()));
  }
  return result;
}

using ExactSkeleton = CGAL::Straight_skeleton_2<ExactKernel>;

/// A straight skeleton built in the inexact kernel (its events are exact predicates)
/// and converted once to the exact kernel, in which every offset of it is constructed.
boost::shared_ptr<ExactSkeleton> toExactSkeleton(
    const boost::shared_ptr<CGAL::Straight_skeleton_2<InexactKernel>>& skeleton,
    const std::string& ring) {
  if (!skeleton) {
    throw InternalError("offset", "the straight skeleton of " + ring + " could not be built");
  }
  return CGAL::convert_straight_skeleton_2<ExactSkeleton>(*skeleton);
}

/// The offset contours of `skeleton` at `distance`.
std::vector<boost::shared_ptr<ExactPolygon>> offsetContours(const ExactSkeleton& skeleton,
                                                            double distance) {
  return CGAL::create_offset_polygons_2<ExactPolygon>(distance, skeleton, ExactKernel());
}

/// A hole grown by its exterior straight skeleton: the outline of the offset (pockets
/// that the growth encloses are filled, they are out of reach anyway).
ExactPolygon grownHole(const ExactSkeleton& skeleton, const Ring& hole, double distance) {
  // The result holds a bounding frame and the offset outline(s); the frame is the
  // largest, the outline the next largest.
  std::vector<std::pair<double, ExactPolygon>> by_area;
  for (const auto& offset : offsetContours(skeleton, distance)) {
    by_area.emplace_back(std::abs(CGAL::to_double(offset->area())), *offset);
  }
  std::sort(by_area.begin(), by_area.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  if (by_area.size() < 2) return toExactCcw(hole);
  ExactPolygon outline = by_area[1].second;
  if (outline.orientation() == CGAL::CLOCKWISE) outline.reverse_orientation();
  return outline;
}

PolygonWithHoles toPolygonWithHoles(const ExactPolygonWithHoles& polygon) {
  PolygonWithHoles result;
  result.hull = toRing(polygon.outer_boundary(), true);
  for (auto it = polygon.holes_begin(); it != polygon.holes_end(); ++it) {
    Ring hole = toRing(*it, false);
    if (hole.size() >= 3) result.holes.push_back(std::move(hole));
  }
  return result;
}

/// The reflex vertices of the ring taken counter-clockwise.
std::size_t reflexVertexCount(const Ring& ring) {
  const std::size_t n = ring.size();
  const bool counter_clockwise = signedArea(ring) > 0.0;
  std::size_t reflex = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double turn = cross(ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]);
    if (counter_clockwise ? turn < 0.0 : turn > 0.0) ++reflex;
  }
  return reflex;
}

/// Throws InvalidInputError when the straight skeleton of `ring` would hold more than
/// kMaxSkeletonPairs vertex pairs (see wall_offset.h); `name` names it ("the hull", "hole 2").
void checkSkeletonSize(const Ring& ring, const std::string& name) {
  const std::size_t n = ring.size();
  const std::size_t reflex = reflexVertexCount(ring);
  const double pairs = skeletonPairs(ring);
  if (pairs <= kMaxSkeletonPairs) return;
  std::ostringstream message;
  message << name << " has " << n << " vertices, " << reflex
          << " of them reflex: its wall offset (a straight skeleton, which keeps data for every "
             "pair of a vertex and a reflex vertex, about 50 bytes each on a hull) would hold "
          << static_cast<long long>(pairs) << " pairs, " << std::setprecision(3)
          << pairs / kMaxSkeletonPairs << " times the limit of "
          << static_cast<long long>(kMaxSkeletonPairs) << ": simplify " << name
          << " to fewer vertices (noise far below wall_distance and the sweep distance only adds "
             "vertices; boundary_simplification does it within a share of the sweep distance) or "
             "plan the area in parts";
  throw SizeLimitError(message.str());
}

/// The parts of the offset free area in `set`, largest first; throws when it is empty.
OffsetFreeArea offsetParts(const ExactPolygonSet& set, double wall_distance) {
  std::vector<ExactPolygonWithHoles> parts;
  set.polygons_with_holes(std::back_inserter(parts));
  parts.erase(std::remove_if(parts.begin(), parts.end(),
                             [](const ExactPolygonWithHoles& p) { return exactArea(p) <= 0.0; }),
              parts.end());
  if (parts.empty()) {
    std::ostringstream message;
    message << "the offset free area is empty: wall_distance " << wall_distance
            << " m leaves no point far enough from the hull and the holes";
    throw InvalidInputError(message.str());
  }
  std::sort(parts.begin(), parts.end(),
            [](const ExactPolygonWithHoles& a, const ExactPolygonWithHoles& b) {
              return exactArea(a) > exactArea(b);
            });
  OffsetFreeArea result;
  for (const ExactPolygonWithHoles& part : parts) result.parts.push_back(toPolygonWithHoles(part));
  return result;
}

}  // namespace

double skeletonPairs(const Ring& ring) {
  return static_cast<double>(ring.size()) * static_cast<double>(reflexVertexCount(ring));
}

bool fitsSkeletonLimit(const PolygonWithHoles& area) {
  if (skeletonPairs(area.hull) > kMaxSkeletonPairs) return false;
  for (const Ring& hole : area.holes) {
    if (skeletonPairs(hole) > kMaxSkeletonPairs) return false;
  }
  return true;
}

/// The hull's interior skeleton and each hole's exterior one, up to the largest distance.
struct WallOffset::Skeletons {
  const PolygonWithHoles* free_area = nullptr;
  double max_distance = 0.0;
  boost::shared_ptr<ExactSkeleton> hull;
  std::vector<boost::shared_ptr<ExactSkeleton>> holes;
};

WallOffset::WallOffset(const PolygonWithHoles& free_area, double max_distance)
    : skeletons_(std::make_unique<Skeletons>()) {
  checkSkeletonSize(free_area.hull, "the hull");
  for (std::size_t i = 0; i < free_area.holes.size(); ++i) {
    checkSkeletonSize(free_area.holes[i], "hole " + std::to_string(i));
  }
  skeletons_->free_area = &free_area;
  skeletons_->max_distance = max_distance;
  skeletons_->holes.resize(free_area.holes.size());
  // The rings' skeletons are independent: built on every hardware thread (ring 0 the hull).
  parallelForInOrder(1 + free_area.holes.size(), [&](std::size_t ring) {
    if (ring == 0) {
      const InexactPolygon hull = toInexactCcw(free_area.hull);
      const std::vector<InexactPolygon> no_holes;
      skeletons_->hull =
          toExactSkeleton(CGAL::CGAL_SS_i::create_partial_interior_straight_skeleton_2(
                              max_distance, hull.vertices_begin(), hull.vertices_end(),
                              no_holes.begin(), no_holes.end(), InexactKernel()),
                          "the hull");
      return;
    }
    const InexactPolygon hole = toInexactCcw(free_area.holes[ring - 1]);
    skeletons_->holes[ring - 1] = toExactSkeleton(
        CGAL::CGAL_SS_i::create_partial_exterior_straight_skeleton_2(
            max_distance, hole.vertices_begin(), hole.vertices_end(), InexactKernel()),
        "hole " + std::to_string(ring - 1));
  });
}

WallOffset::~WallOffset() = default;

OffsetFreeArea WallOffset::at(double distance) const {
  const Skeletons& skeletons = *skeletons_;
  if (!(distance > 0.0 && distance <= skeletons.max_distance)) {
    throw InternalError("offset", "an offset distance beyond the skeletons was asked for");
  }
  // The offsets of the rings on every hardware thread, then subtracted in order.
  std::vector<boost::shared_ptr<ExactPolygon>> shrunk_hull;
  std::vector<ExactPolygon> grown_holes(skeletons.holes.size());
  parallelForInOrder(1 + skeletons.holes.size(), [&](std::size_t ring) {
    if (ring == 0) {
      shrunk_hull = offsetContours(*skeletons.hull, distance);
    } else {
      grown_holes[ring - 1] =
          grownHole(*skeletons.holes[ring - 1], skeletons.free_area->holes[ring - 1], distance);
    }
  });
  ExactPolygonSet set;
  for (const auto& part : shrunk_hull) {
    ExactPolygon polygon = *part;
    if (polygon.size() < 3) continue;
    if (polygon.orientation() == CGAL::CLOCKWISE) polygon.reverse_orientation();
    set.join(polygon);
  }
  for (const ExactPolygon& hole : grown_holes) set.difference(hole);
  return offsetParts(set, distance);
}

OffsetFreeArea computeOffsetFreeArea(const PolygonWithHoles& free_area, double wall_distance) {
  if (wall_distance > 0.0) return WallOffset(free_area, wall_distance).at(wall_distance);
  ExactPolygonSet set;
  set.insert(toExactCcw(free_area.hull));
  for (const Ring& hole : free_area.holes) set.difference(toExactCcw(hole));
  return offsetParts(set, wall_distance);
}

}  // namespace kinematic_coverage::core
