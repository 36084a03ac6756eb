#include "polygon_coverage_ros_bridge/validation/polygon_cleaner.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/box_intersection_d.h>

#include <iterator>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/validation/polygon_validator.h"

namespace kinematic_coverage::core {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using EPoint = Kernel::Point_2;
using ESegment = Kernel::Segment_2;
using EPolygon = CGAL::Polygon_2<Kernel>;
using EPolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;
using EPolygonSet = CGAL::Polygon_set_2<Kernel>;
using EdgeBox = CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t>;

/// How the boundaries of two rings meet.
struct RingContact {
  bool along_edge = false;  ///< some edges overlap over a positive length
  std::set<EPoint> points;  ///< isolated points where the boundaries meet
};

std::string ringName(std::size_t ring) {
  return ring == 0 ? "hull" : "hole " + std::to_string(ring - 1);
}

/// Drops duplicate consecutive vertices (also a closing copy of the first vertex).
std::vector<EPoint> dropDuplicateVertices(const Ring& ring) {
  std::vector<EPoint> points;
  for (const Point2& p : ring) {
    const EPoint e(p.x(), p.y());
    if (points.empty() || points.back() != e) points.push_back(e);
  }
  while (points.size() > 1 && points.back() == points.front()) points.pop_back();
  return points;
}

EPolygon counterClockwise(const std::vector<EPoint>& points) {
  EPolygon polygon(points.begin(), points.end());
  if (polygon.is_clockwise_oriented()) polygon.reverse_orientation();
  return polygon;
}

/// The contacts between the boundaries of different rings (ring 0 is the hull).
std::map<std::pair<std::size_t, std::size_t>, RingContact> findContacts(
    const std::vector<std::vector<EPoint>>& rings) {
  std::vector<std::pair<std::size_t, std::size_t>> edges;  // (ring, first vertex)
  std::vector<EdgeBox> boxes;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const std::size_t n = rings[r].size();
    for (std::size_t k = 0; k < n; ++k) {
      boxes.emplace_back(rings[r][k].bbox() + rings[r][(k + 1) % n].bbox(), edges.size());
      edges.emplace_back(r, k);
    }
  }
  auto segment = [&](std::size_t edge) {
    const auto& ring = rings[edges[edge].first];
    const std::size_t k = edges[edge].second;
    return ESegment(ring[k], ring[(k + 1) % ring.size()]);
  };
  std::map<std::pair<std::size_t, std::size_t>, RingContact> contacts;
  auto report = [&](const EdgeBox& a, const EdgeBox& b) {
    std::size_t ring_a = edges[a.info()].first;
    std::size_t ring_b = edges[b.info()].first;
    if (ring_a == ring_b) return;
    const ESegment sa = segment(a.info());
    const ESegment sb = segment(b.info());
    if (!CGAL::do_intersect(sa, sb)) return;
    RingContact& contact = contacts[std::minmax(ring_a, ring_b)];
    const auto result = CGAL::intersection(sa, sb);
    if (const EPoint* p = boost::get<EPoint>(&*result)) {
      contact.points.insert(*p);
    } else {
      contact.along_edge = true;
    }
  };
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), report, std::ptrdiff_t(10),
                                CGAL::Box_intersection_d::CLOSED);
  return contacts;
}

Kernel::FT exactArea(const std::vector<EPolygonWithHoles>& parts) {
  Kernel::FT total = 0;
  for (const EPolygonWithHoles& part : parts) {
    total += CGAL::abs(part.outer_boundary().area());
    for (auto hole = part.holes_begin(); hole != part.holes_end(); ++hole) {
      total -= CGAL::abs(hole->area());
    }
  }
  return total;
}

/// Splits a closed boundary that may visit a vertex twice (CGAL's "relatively simple"
/// boundaries: a hole touching the hull at one point) into simple loops.
std::vector<std::vector<EPoint>> splitAtRepeatedVertices(const EPolygon& boundary) {
  std::vector<std::vector<EPoint>> loops;
  std::vector<EPoint> stack;
  std::map<EPoint, std::size_t> position;
  for (auto v = boundary.vertices_begin(); v != boundary.vertices_end(); ++v) {
    const auto seen = position.find(*v);
    if (seen == position.end()) {
      position.emplace(*v, stack.size());
      stack.push_back(*v);
      continue;
    }
    std::vector<EPoint> loop(stack.begin() + static_cast<std::ptrdiff_t>(seen->second),
                             stack.end());
    for (std::size_t k = seen->second + 1; k < stack.size(); ++k) position.erase(stack[k]);
    stack.resize(seen->second + 1);
    if (loop.size() >= 3) loops.push_back(std::move(loop));
  }
  if (stack.size() >= 3) loops.push_back(std::move(stack));
  return loops;
}

bool isCounterClockwise(const std::vector<EPoint>& loop) {
  return EPolygon(loop.begin(), loop.end()).orientation() == CGAL::COUNTERCLOCKWISE;
}

/// A loop rounded to doubles, without the duplicates that rounding may create.
Ring toRing(const std::vector<EPoint>& loop) {
  Ring ring;
  for (const EPoint& p : loop) {
    const Point2 q(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
    if (ring.empty() || ring.back() != q) ring.push_back(q);
  }
  while (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
  return ring;
}

/// How many extra parts the free area's interior falls into because its boundary loops
/// (loop 0 the hull, the others holes; simple, meeting at shared vertices only) touch
/// in cycles: each independent cycle of the touching graph encloses a part of its own.
std::size_t touchingCycles(const std::vector<std::vector<EPoint>>& loops) {
  std::vector<std::size_t> parent(loops.size());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = i;
  auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::map<EPoint, std::size_t> first_loop;
  std::size_t cycles = 0;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    for (const EPoint& p : loops[l]) {
      const auto [it, inserted] = first_loop.emplace(p, l);
      if (inserted || it->second == l) continue;
      const std::size_t a = root(it->second), b = root(l);
      if (a == b) {
        ++cycles;
      } else {
        parent[a] = b;
      }
    }
  }
  return cycles;
}

std::string disconnectedMessage(std::size_t parts) {
  return "the holes split the free area into " + std::to_string(parts) +
         " disconnected parts (parts that meet only at single points count as "
         "disconnected): one connected area is needed";
}

/// The rings (hull first) without repeated consecutive vertices; a warning per ring that
/// had some.
std::vector<std::vector<EPoint>> ringsWithoutDuplicates(const PolygonWithHoles& raw,
                                                        std::vector<std::string>* warnings) {
  std::vector<std::vector<EPoint>> rings;
  for (std::size_t r = 0; r <= raw.holes.size(); ++r) {
    const Ring& input = r == 0 ? raw.hull : raw.holes[r - 1];
    rings.push_back(dropDuplicateVertices(input));
    const std::size_t dropped = input.size() - rings.back().size();
    if (dropped > 0) {
      warnings->push_back(ringName(r) + ": " + std::to_string(dropped) +
                          (dropped == 1 ? " duplicate consecutive vertex dropped"
                                        : " duplicate consecutive vertices dropped"));
    }
  }
  return rings;
}

/// A warning per cleaning step the rings need: holes that cross or touch the hull (which
/// is cut back), holes that overlap, touch or nest (which are merged).
void contactWarnings(const std::vector<std::vector<EPoint>>& rings,
                     const std::vector<EPolygon>& polygons, std::vector<std::string>* warnings) {
  const auto contacts = findContacts(rings);
  for (const auto& [pair, contact] : contacts) {
    const auto [a, b] = pair;
    const bool several_points = contact.points.size() >= 2;
    if (a == 0) {
      std::vector<EPolygonWithHoles> inside;
      CGAL::intersection(polygons[0], polygons[b], std::back_inserter(inside));
      if (exactArea(inside) < CGAL::abs(polygons[b].area())) {
        warnings->push_back(ringName(b) +
                            " crosses the hull: its part outside the hull is cut off "
                            "and the hull is cut back");
      } else if (contact.along_edge || several_points) {
        warnings->push_back(ringName(b) + " touches the hull " +
                            (contact.along_edge ? "along an edge" : "at several points") +
                            ": the hull is cut back");
      }
      continue;
    }
    if (CGAL::do_intersect(polygons[a], polygons[b], CGAL::Tag_false())) {
      warnings->push_back(ringName(a) + " and " + ringName(b) + " overlap: merged");
    } else if (contact.along_edge || several_points) {
      warnings->push_back(ringName(a) + " and " + ringName(b) + " touch " +
                          (contact.along_edge ? "along an edge" : "at several points") +
                          ": merged");
    }
  }
  std::vector<CGAL::Bbox_2> boxes;
  for (const EPolygon& polygon : polygons) boxes.push_back(polygon.bbox());
  for (std::size_t a = 1; a < polygons.size(); ++a) {
    for (std::size_t b = 1; b < polygons.size(); ++b) {
      const bool nested = a != b && boxes[b].xmin() <= boxes[a].xmin() &&
                          boxes[a].xmax() <= boxes[b].xmax() &&
                          boxes[b].ymin() <= boxes[a].ymin() && boxes[a].ymax() <= boxes[b].ymax();
      if (!nested || contacts.count(std::minmax(a, b)) > 0) continue;
      if (polygons[b].bounded_side(polygons[a][0]) == CGAL::ON_BOUNDED_SIDE) {
        warnings->push_back(ringName(a) + " lies inside " + ringName(b) + ": merged");
      }
    }
  }
}

/// The free area's boundary loops: its one hull loop first, then its hole loops.
struct FreeAreaLoops {
  std::vector<EPoint> hull;
  std::vector<std::vector<EPoint>> holes;
};

/// The hull minus the union of the holes, as simple loops (split where a boundary
/// repeats a vertex). InvalidInputError when it is empty or not one connected area.
FreeAreaLoops freeAreaLoops(const std::vector<EPolygon>& polygons) {
  EPolygonSet holes;
  holes.join(polygons.begin() + 1, polygons.end());
  EPolygonSet free_area(polygons[0]);
  free_area.difference(holes);
  std::vector<EPolygonWithHoles> parts;
  free_area.polygons_with_holes(std::back_inserter(parts));
  if (parts.empty()) {
    throw InvalidInputError("the holes cover the whole hull: the free area is empty");
  }
  if (parts.size() > 1) throw InvalidInputError(disconnectedMessage(parts.size()));

  std::vector<std::vector<EPoint>> hulls;
  std::vector<std::vector<EPoint>> hole_loops;
  for (auto& loop : splitAtRepeatedVertices(parts[0].outer_boundary())) {
    (isCounterClockwise(loop) ? hulls : hole_loops).push_back(std::move(loop));
  }
  for (auto hole = parts[0].holes_begin(); hole != parts[0].holes_end(); ++hole) {
    for (auto& loop : splitAtRepeatedVertices(*hole)) {
      if (isCounterClockwise(loop)) {
        hulls.push_back(std::move(loop));
      } else {
        hole_loops.push_back(std::move(loop));
      }
    }
  }
  if (hulls.size() != 1) throw InvalidInputError(disconnectedMessage(hulls.size()));
  std::vector<std::vector<EPoint>> loops = hulls;
  loops.insert(loops.end(), hole_loops.begin(), hole_loops.end());
  if (const std::size_t cycles = touchingCycles(loops); cycles > 0) {
    throw InvalidInputError(disconnectedMessage(1 + cycles));
  }
  return {std::move(hulls[0]), std::move(hole_loops)};
}

/// A cleaned loop as a ring, checked again: rounding to doubles must not break it.
Ring validatedRing(const std::vector<EPoint>& loop, const std::string& name) {
  Ring ring = toRing(loop);
  try {
    PolygonValidator().validateRing(ring, name);
  } catch (const InvalidInputError& error) {
    throw InvalidInputError(std::string("after cleaning, the ") + error.what() +
                            ": the input has features below floating-point resolution");
  }
  return ring;
}

}  // namespace

CleanedPolygon PolygonCleaner::clean(const PolygonWithHoles& raw) const {
  CleanedPolygon cleaned;
  const std::vector<std::vector<EPoint>> rings = ringsWithoutDuplicates(raw, &cleaned.warnings);
  std::vector<EPolygon> polygons;
  for (const auto& ring : rings) polygons.push_back(counterClockwise(ring));
  contactWarnings(rings, polygons, &cleaned.warnings);
  const FreeAreaLoops loops = freeAreaLoops(polygons);
  cleaned.free_area.hull = validatedRing(loops.hull, "hull");
  for (std::size_t h = 0; h < loops.holes.size(); ++h) {
    cleaned.free_area.holes.push_back(
        validatedRing(loops.holes[h], "cleaned hole " + std::to_string(h)));
  }
  return cleaned;
}

}  // namespace kinematic_coverage::core
