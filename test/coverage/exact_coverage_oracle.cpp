#include "test/coverage/exact_coverage_oracle.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/minkowski_sum_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <utility>

namespace kinematic_coverage::core {
namespace testing {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using FT = Kernel::FT;
using ExactPoint = Kernel::Point_2;
using ExactPolygon = CGAL::Polygon_2<Kernel>;
using ExactPolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;
using ExactPolygonSet = CGAL::Polygon_set_2<Kernel>;

/// Consecutive poses closer than this are at the same position (a rotation in place, whose
/// positions agree up to rounding): their seen area is the union of their two footprints,
/// not the convex hull (docs/REFERENCE.md, Sensor footprint and coverage).
constexpr double kSamePosition = 1e-9;

/// A pose continues a straight run when its heading is the run's within this angle
/// (radians) and its position lies within kStraightRunOffset (metres) of the run's line:
/// sampling a segment rounds to about 1e-15 relative, far below both.
constexpr double kStraightRunAngle = 1e-12;
constexpr double kStraightRunOffset = 1e-9;

/// The erosion's band polygons are grown by this factor so that rounding their corners to
/// doubles (about 1e-16 relative) never leaves a point nearer than wall_distance to the
/// boundary outside the band: the eroded set stays a subset of the exact one.
constexpr double kOutward = 1.0 + 1e-9;

ExactPoint exact(const Point2& p) { return ExactPoint(p.x(), p.y()); }

Point2 approximate(const ExactPoint& p) { return {CGAL::to_double(p.x()), CGAL::to_double(p.y())}; }

ExactPolygon exactRing(const Ring& ring, CGAL::Orientation orientation) {
  ExactPolygon polygon;
  for (const Point2& p : ring) {
    const ExactPoint q = exact(p);
    if (polygon.is_empty() ||
        (q != polygon.container().back() && q != polygon.container().front())) {
      polygon.push_back(q);
    }
  }
  if (polygon.size() < 3 || !polygon.is_simple()) {
    throw std::invalid_argument("exact coverage oracle: a ring is degenerate or not simple");
  }
  if (polygon.orientation() != orientation) polygon.reverse_orientation();
  return polygon;
}

/// Exact area of a polygon set: outer boundaries are counter-clockwise, holes clockwise.
FT exactArea(const ExactPolygonSet& set) {
  std::vector<ExactPolygonWithHoles> parts;
  set.polygons_with_holes(std::back_inserter(parts));
  FT total = 0;
  for (const ExactPolygonWithHoles& part : parts) {
    total += part.outer_boundary().area();
    for (auto hole = part.holes_begin(); hole != part.holes_end(); ++hole) total += hole->area();
  }
  return total;
}

/// A regular polygon with `sides` vertices at `radius` from `centre`, counter-clockwise.
ExactPolygon regularPolygon(const Point2& centre, double radius, int sides) {
  ExactPolygon polygon;
  for (int k = 0; k < sides; ++k) {
    const double angle = 2.0 * M_PI * k / sides;
    polygon.push_back(exact(centre + radius * Point2(std::cos(angle), std::sin(angle))));
  }
  return polygon;
}

/// Length of the rings of a polygon set and the total turning at its convex vertices (the
/// set on the left of every ring, as CGAL returns them).
void perimeterAndConvexTurning(const ExactPolygonSet& set, double& perimeter, double& turning) {
  std::vector<ExactPolygonWithHoles> parts;
  set.polygons_with_holes(std::back_inserter(parts));
  perimeter = 0.0;
  turning = 0.0;
  auto add = [&](const ExactPolygon& ring) {
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point2 a = approximate(ring[i]);
      const Point2 b = approximate(ring[(i + 1) % n]);
      const Point2 c = approximate(ring[(i + 2) % n]);
      const Point2 in = b - a;
      const Point2 out = c - b;
      perimeter += in.norm();
      const double turn =
          std::atan2(in.x() * out.y() - in.y() * out.x(), in.x() * out.x() + in.y() * out.y());
      turning += std::max(0.0, turn);
    }
  };
  for (const ExactPolygonWithHoles& part : parts) {
    add(part.outer_boundary());
    for (auto hole = part.holes_begin(); hole != part.holes_end(); ++hole) add(*hole);
  }
}

/// An area given as hull minus holes, as an exact polygon set; `rings` receives its rings,
/// each oriented with the area on its left (hull counter-clockwise, holes clockwise).
ExactPolygonSet exactSet(const PolygonWithHoles& area, std::vector<ExactPolygon>& rings) {
  const ExactPolygon hull = exactRing(area.hull, CGAL::COUNTERCLOCKWISE);
  rings.push_back(hull);
  ExactPolygonSet set(hull);
  for (const Ring& hole_ring : area.holes) {
    ExactPolygon hole = exactRing(hole_ring, CGAL::CLOCKWISE);
    rings.push_back(hole);
    hole.reverse_orientation();
    set.difference(hole);
  }
  return set;
}

}  // namespace

OracleFootprint oracleFootprint(const PlannerParameters& parameters) {
  if (parameters.sensor_model == "line") return {parameters.lateral_footprint, 0.0};
  const double d = parameters.sensor_distance;
  return {2.0 * d * std::tan(0.5 * parameters.lateral_fov),
          2.0 * d * std::tan(0.5 * parameters.onward_fov)};
}

struct ExactCoverageOracle::Impl {
  OracleFootprint footprint;
  int disk_sides = 0;
  std::vector<ExactPolygon> free_rings;
  ExactPolygonSet free_area;
  ExactPolygonSet offset_free_area;
  ExactPolygonSet reachable_area;
  double free_area_m2 = 0.0;
  double offset_free_area_m2 = 0.0;
  double reachable_area_m2 = 0.0;
  int offset_parts = 0;
  ReachableAreaErrorBound error_bound;

  Impl(const PolygonWithHoles& free, const OracleFootprint& sensor, int sides)
      : footprint(sensor), disk_sides(sides) {
    if (!(footprint.width > 0.0) || !(footprint.length >= 0.0) || disk_sides < 8) {
      throw std::invalid_argument("exact coverage oracle: invalid footprint or disk");
    }
    // F: hull minus holes (docs/REFERENCE.md, Geometry and input rules).
    free_area = exactSet(free, free_rings);
    free_area_m2 = CGAL::to_double(exactArea(free_area));
  }

  void setOffsetFreeArea(ExactPolygonSet offset) {
    offset_free_area = std::move(offset);
    offset_free_area_m2 = CGAL::to_double(exactArea(offset_free_area));
    offset_parts = static_cast<int>(offset_free_area.number_of_polygons_with_holes());
  }

  // The offset free area E (docs/REFERENCE.md, Geometry and input rules): the points of F
  // at least w from the hull and from every hole, i.e. F minus the band of points nearer
  // than w to its boundary. The band is the union of a rectangle of half-width w along
  // every edge and, at every vertex that is reflex in F, a regular polygon CIRCUMSCRIBED
  // about the disk of radius w.
  // Points of F whose nearest boundary point lies inside an edge are in its rectangle; a
  // point of F whose nearest boundary point is a vertex sees that vertex as reflex (at a
  // convex vertex the segment to the point would leave F first). So the band holds every
  // point of F nearer than w to the boundary, and E is a SUBSET of the exact erosion E_w.
  // The band lies within w' = w / cos(pi / n) of the boundary (n = disk_sides), so E holds
  // E_w', and the area error is
  //   area(E_w) - area(E) <= area{p in F : w <= d(p) < w'}
  //                       <= (w' - w) (perimeter(F) + pi w' reflex_vertices(F)),
  // by the coarea formula: the level line d = t runs parallel to the edges (no longer than
  // each) and along arcs of radius t and angle < pi about the reflex vertices. With n = 256,
  // w' - w = 7.5e-5 w: under 0.03 m^2 for w <= 1.5 m, a 200 m perimeter and 50 reflex
  // vertices. (Where a strait's width lies between 2 w and 2 w', E_w has a thread that E
  // lacks; the dilation below then differs by more, but only in that 0.1 mm window.)
  void erode(double wall_distance) {
    if (!(wall_distance > 0.0)) {
      throw std::invalid_argument("exact coverage oracle: the wall distance must be > 0");
    }
    const double w = wall_distance * kOutward;
    const double w_outer = w / std::cos(M_PI / disk_sides);
    // Rectangles reach this far past their edges' ends, so that rounding never leaves a
    // gap between neighbouring rectangles at a convex vertex (a gap would leave a sliver in
    // E, which the dilation would grow); their points stay within sqrt(w^2 + extension^2),
    // less than w'.
    const double extension = 1e-6 * wall_distance;
    std::vector<ExactPolygon> band;
    double perimeter = 0.0;
    int reflex_vertices = 0;
    for (const ExactPolygon& ring : free_rings) {
      const std::size_t n = ring.size();
      for (std::size_t i = 0; i < n; ++i) {
        const ExactPoint& previous = ring[(i + n - 1) % n];
        const ExactPoint& a = ring[i];
        const ExactPoint& b = ring[(i + 1) % n];
        const Point2 pa = approximate(a);
        const Point2 pb = approximate(b);
        const double length = (pb - pa).norm();
        perimeter += length;
        const Point2 along = (pb - pa) / length;
        const Point2 normal(-along.y(), along.x());
        const Point2 s = pa - extension * along;
        const Point2 e = pb + extension * along;
        ExactPolygon rectangle;
        rectangle.push_back(exact(s - w * normal));
        rectangle.push_back(exact(e - w * normal));
        rectangle.push_back(exact(e + w * normal));
        rectangle.push_back(exact(s + w * normal));
        band.push_back(std::move(rectangle));
        if (CGAL::orientation(previous, a, b) == CGAL::RIGHT_TURN) {
          ++reflex_vertices;
          band.push_back(regularPolygon(pa, w_outer, disk_sides));
        }
      }
    }
    ExactPolygonSet band_set;
    band_set.join(band.begin(), band.end());
    ExactPolygonSet offset = free_area;
    offset.difference(band_set);
    setOffsetFreeArea(std::move(offset));
    error_bound.erosion_m2 =
        (w_outer - wall_distance) * (perimeter + M_PI * w_outer * reflex_vertices);
  }

  // The reachable area R (docs/REFERENCE.md, Sensor footprint and coverage): F within
  // r = L / 2 of E, with E dilated (Minkowski sum) by a regular polygon INSCRIBED in the
  // disk of radius r, so that R is a subset of the exact F within r of E. That polygon
  // holds the disk of radius r cos(pi / n), so
  //   area(E (+) disk_r) - area(E (+) polygon) <= r (1 - cos(pi / n)) (perimeter(E) + r T(E)),
  // T(E) the total turning at E's convex vertices (the level line at distance t from E runs
  // parallel to E's edges and along arcs of radius t about its convex vertices).
  void grow() {
    const double r = 0.5 * footprint.length;
    if (r == 0.0) {
      reachable_area = offset_free_area;
    } else {
      const ExactPolygon disk = regularPolygon(Point2::Zero(), r, disk_sides);
      const CGAL::Bbox_2 disk_box = disk.bbox();
      std::vector<ExactPolygonWithHoles> parts;
      offset_free_area.polygons_with_holes(std::back_inserter(parts));
      std::vector<ExactPolygonWithHoles> grown;
      for (const ExactPolygonWithHoles& part : parts) {
        // A hole narrower than the disk along x or y is filled by the sum: from each of its
        // points E lies less than r away along that axis, and D holds that offset. Such
        // holes are left out here because CGAL 5.5's own filter of them (Hole_filter_2)
        // erases them from a std::deque through iterators that each erase invalidates
        // (std::bad_alloc on some star maps of the family soak); with none left to filter
        // it erases nothing.
        ExactPolygonWithHoles kept(part.outer_boundary());
        for (auto hole = part.holes_begin(); hole != part.holes_end(); ++hole) {
          const CGAL::Bbox_2 box = hole->bbox();
          if (box.xmax() - box.xmin() >= disk_box.xmax() - disk_box.xmin() &&
              box.ymax() - box.ymin() >= disk_box.ymax() - disk_box.ymin()) {
            kept.add_hole(*hole);
          }
        }
        grown.push_back(CGAL::minkowski_sum_2(kept, disk));
      }
      reachable_area.join(grown.begin(), grown.end());
      reachable_area.intersection(free_area);
      double offset_perimeter = 0.0;
      double offset_turning = 0.0;
      perimeterAndConvexTurning(offset_free_area, offset_perimeter, offset_turning);
      error_bound.dilation_m2 =
          r * (1.0 - std::cos(M_PI / disk_sides)) * (offset_perimeter + r * offset_turning);
    }
    reachable_area_m2 = CGAL::to_double(exactArea(reachable_area));
  }

  /// The footprint's corners at a pose, counter-clockwise (pairwise equal for a line sensor).
  std::array<ExactPoint, 4> corners(const Pose2& pose) const {
    const Point2 along(std::cos(pose.yaw), std::sin(pose.yaw));
    const Point2 across(-along.y(), along.x());
    const Point2 centre(pose.x, pose.y);
    const Point2 half_along = 0.5 * footprint.length * along;
    const Point2 half_across = 0.5 * footprint.width * across;
    return {exact(centre - half_along - half_across), exact(centre + half_along - half_across),
            exact(centre + half_along + half_across), exact(centre - half_along + half_across)};
  }

  /// The convex hull of `points` when it has an area (a line sensor's footprint has none).
  template <typename Iterator>
  static void addHull(Iterator begin, Iterator end, std::vector<ExactPolygon>& pieces) {
    std::vector<ExactPoint> hull;
    CGAL::convex_hull_2(begin, end, std::back_inserter(hull));
    if (hull.size() >= 3) pieces.emplace_back(hull.begin(), hull.end());
  }
};

ExactCoverageOracle::ExactCoverageOracle(const PolygonWithHoles& free_area, double wall_distance,
                                         const OracleFootprint& footprint, int disk_sides)
    : impl_(std::make_unique<Impl>(free_area, footprint, disk_sides)) {
  impl_->erode(wall_distance);
  impl_->grow();
}

ExactCoverageOracle::ExactCoverageOracle(const PolygonWithHoles& free_area,
                                         const std::vector<PolygonWithHoles>& offset_parts,
                                         const OracleFootprint& footprint, int disk_sides)
    : impl_(std::make_unique<Impl>(free_area, footprint, disk_sides)) {
  std::vector<ExactPolygon> rings;
  ExactPolygonSet offset;
  for (const PolygonWithHoles& part : offset_parts) offset.join(exactSet(part, rings));
  offset.intersection(impl_->free_area);
  impl_->setOffsetFreeArea(std::move(offset));
  impl_->grow();
}

ExactCoverageOracle::~ExactCoverageOracle() = default;

double ExactCoverageOracle::freeAreaM2() const { return impl_->free_area_m2; }
double ExactCoverageOracle::offsetFreeAreaM2() const { return impl_->offset_free_area_m2; }
double ExactCoverageOracle::reachableAreaM2() const { return impl_->reachable_area_m2; }
int ExactCoverageOracle::offsetFreeAreaParts() const { return impl_->offset_parts; }
const ReachableAreaErrorBound& ExactCoverageOracle::reachableErrorBound() const {
  return impl_->error_bound;
}

OffsetFreeAreaDifference ExactCoverageOracle::compareOffsetFreeArea(
    const std::vector<PolygonWithHoles>& other) const {
  std::vector<ExactPolygon> rings;
  ExactPolygonSet given;
  for (const PolygonWithHoles& part : other) given.join(exactSet(part, rings));
  ExactPolygonSet missing = impl_->offset_free_area;
  missing.difference(given);
  ExactPolygonSet extra = given;
  extra.difference(impl_->offset_free_area);
  return {CGAL::to_double(exactArea(missing)), CGAL::to_double(exactArea(extra))};
}

ExactCoverage ExactCoverageOracle::measure(const std::vector<Pose2>& poses,
                                           bool merge_straight_runs) const {
  const Impl& m = *impl_;
  // The seen area (docs/REFERENCE.md, Sensor footprint and coverage): every footprint, and
  // the convex hull of each two consecutive footprints at different positions (which holds
  // both footprints). A line sensor's footprints are segments: only hulls have an area.
  std::vector<ExactPolygon> pieces;
  pieces.reserve(poses.size() + 1);
  auto addFootprint = [&](const Pose2& pose) {
    const std::array<ExactPoint, 4> corners = m.corners(pose);
    Impl::addHull(corners.begin(), corners.end(), pieces);
  };
  // The last pose of the straight run starting at `first`: each next pose has the run's
  // heading, lies on its line and advances along it.
  auto straightRunEnd = [&](std::size_t first) {
    const Pose2& origin = poses[first];
    const Point2 along(std::cos(origin.yaw), std::sin(origin.yaw));
    std::size_t last = first;
    while (last + 1 < poses.size()) {
      const Pose2& next = poses[last + 1];
      const Point2 offset(next.x - origin.x, next.y - origin.y);
      const Point2 step(next.x - poses[last].x, next.y - poses[last].y);
      if (std::abs(std::remainder(next.yaw - origin.yaw, 2.0 * M_PI)) > kStraightRunAngle ||
          std::abs(along.x() * offset.y() - along.y() * offset.x()) > kStraightRunOffset ||
          step.dot(along) <= kSamePosition) {
        break;
      }
      ++last;
    }
    return last;
  };
  if (poses.size() == 1) addFootprint(poses.front());
  for (std::size_t i = 0; i + 1 < poses.size();) {
    const std::size_t last = merge_straight_runs ? std::max(straightRunEnd(i), i + 1) : i + 1;
    const Pose2& a = poses[i];
    const Pose2& b = poses[last];
    i = last;
    if (std::hypot(b.x - a.x, b.y - a.y) > kSamePosition) {
      std::array<ExactPoint, 8> corners;
      const std::array<ExactPoint, 4> ca = m.corners(a);
      const std::array<ExactPoint, 4> cb = m.corners(b);
      std::copy(ca.begin(), ca.end(), corners.begin());
      std::copy(cb.begin(), cb.end(), corners.begin() + 4);
      Impl::addHull(corners.begin(), corners.end(), pieces);
    } else {
      addFootprint(a);
      addFootprint(b);
    }
  }
  ExactPolygonSet seen;
  seen.join(pieces.begin(), pieces.end());
  seen.intersection(m.free_area);

  ExactCoverage result;
  result.free_area_m2 = m.free_area_m2;
  result.reachable_area_m2 = m.reachable_area_m2;
  result.seen_free_area_m2 = CGAL::to_double(exactArea(seen));
  seen.intersection(m.reachable_area);
  result.seen_reachable_area_m2 = CGAL::to_double(exactArea(seen));
  result.coverage_percent = 100.0 * result.seen_free_area_m2 / result.free_area_m2;
  result.reachable_coverage_percent =
      m.reachable_area_m2 > 0.0 ? 100.0 * result.seen_reachable_area_m2 / m.reachable_area_m2 : 0.0;
  return result;
}

}  // namespace testing
}  // namespace kinematic_coverage::core
