#include "polygon_coverage_ros_bridge/repair/unseen_area_repair.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <set>
#include <utility>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"

namespace kinematic_coverage::core {
namespace {

/// Rounds of measuring and patching; each one sees what the patches of the one before
/// left (the rim of a region around a corner that a straight patch cut).
constexpr int kRepairRounds = 3;
/// Cells per unseen region whose nearest boundary points place its patches.
constexpr std::size_t kSamplesPerRegion = 400;
/// Regions smaller than this share of a square footprint width are left: slivers no
/// drivable patch would see more of.
constexpr double kMinRegionShare = 1e-3;
/// A region's cells deeper than this share of the footprint width inside the offset free
/// area are seen from a patch through them; shallower ones from the boundary beside them.
constexpr double kBoundaryReachShare = 0.25;
/// Boundary points of one region farther apart along the boundary than this share of the
/// footprint width get patches of their own.
constexpr double kPatchSplitShare = 1.0;
/// Unseen cells closer than this share of the footprint width are one region: a patch
/// that sees one sees the others, and a ragged sliver along a wall counts as a whole.
constexpr double kJoinShare = 0.25;
/// Excursions shorter than this share of the footprint width see little that their corner
/// does not; longer ones than this share of the footprint diagonal are cut to it.
constexpr double kMinExcursionShare = 0.1;
constexpr double kMaxExcursionShare = 4.0;
/// Excursions per region toward the samples farthest from the boundary.
constexpr int kDeepExcursions = 4;
/// How far along the leg a bump leaves it and rejoins it, in multiples of the far end's
/// distance from the leg, the widest (gentlest turns) first; narrower ones keep farther
/// from the walls beside the far end.
constexpr double kBumpSpreads[] = {2.0, 1.0, 0.5};
/// Legs of the path, nearest to a patch's ends, where its insertion is priced.
constexpr std::size_t kCandidateLegs = 12;
/// A leg's view is sampled at this many steps along its middle (clear of its ends by half
/// a footprint diagonal, where the neighbouring legs' views meet it) and this many each
/// side of it, out to this share of half the footprint width.
constexpr int kLegSamplesAlong = 16;
constexpr int kLegSamplesAcross = 3;
constexpr double kLegSampleReach = 0.95;

/// True when `patch` is an excursion out and back (ExactOffsetExcursions) whose last leg
/// `path` already drives, into its far end or out of it: driving it again sees nothing
/// more. A path through the far end on other legs (a bump that bent a leg out to it, for
/// another region) looks along other headings, and may not see what the excursion would.
bool isDrivenExcursion(const std::vector<Point2>& patch, const std::vector<Point2>& path) {
  if (patch.size() % 2 == 0 || patch.size() < 3 || patch.front() != patch.back()) return false;
  const Point2& apex = patch[patch.size() / 2];
  const Point2& before = patch[patch.size() / 2 - 1];
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (path[i] != apex) continue;
    if ((i > 0 && path[i - 1] == before) || (i + 1 < path.size() && path[i + 1] == before)) {
      return true;
    }
  }
  return false;
}

double totalArea(const std::vector<UnseenRegion>& regions) {
  double sum = 0.0;
  for (const UnseenRegion& region : regions) sum += region.area_m2;
  return sum;
}

}  // namespace

UnseenAreaRepair::UnseenAreaRepair(const PolygonWithHoles& free_area, double wall_distance,
                                   std::vector<PolygonWithHoles> planned_parts,
                                   const FrustumSensor& sensor, const VisibilityGraph& graph,
                                   const SegmentCost& segment_cost,
                                   const std::vector<PolygonWithHoles>* coverage_region)
    : UnseenAreaRepair(
          measuringRaster(free_area, exactOffsetParts(free_area, wall_distance, planned_parts),
                          sensor, coverage_region),
          free_area, wall_distance, planned_parts, sensor, graph, segment_cost) {}

CoverageEvaluator UnseenAreaRepair::measuringRaster(
    const PolygonWithHoles& free_area, const std::vector<PolygonWithHoles>& exact_parts,
    const FrustumSensor& sensor, const std::vector<PolygonWithHoles>* coverage_region) {
  CoverageEvaluator evaluator(free_area, exact_parts, sensor, reportingResolution(),
                              kReportingGridAngle);
  if (coverage_region != nullptr) evaluator.restrictReachableArea(*coverage_region);
  return evaluator;
}

UnseenAreaRepair::UnseenAreaRepair(CoverageEvaluator measuring_raster,
                                   const PolygonWithHoles& free_area, double wall_distance,
                                   std::vector<PolygonWithHoles> patch_areas,
                                   const FrustumSensor& sensor, const VisibilityGraph& graph,
                                   const SegmentCost& segment_cost)
    : patch_areas_(std::move(patch_areas)),
      sensor_(sensor),
      evaluator_(std::move(measuring_raster)),
      graph_(graph),
      segment_cost_(segment_cost),
      min_region_m2_(kMinRegionShare * sensor.width() * sensor.width()),
      join_distance_(kJoinShare * sensor.width()),
      excursions_(free_area, wall_distance, kMinExcursionShare * sensor.width(),
                  kMaxExcursionShare * std::hypot(sensor.width(), sensor.length())) {
  for (const PolygonWithHoles& part : patch_areas_) {
    rings_.push_back(part.hull);
    if (signedArea(rings_.back()) < 0.0) std::reverse(rings_.back().begin(), rings_.back().end());
    for (const Ring& hole : part.holes) {
      rings_.push_back(hole);
      if (signedArea(rings_.back()) > 0.0) std::reverse(rings_.back().begin(), rings_.back().end());
    }
  }
  std::vector<Point2> starts, ends;
  for (std::size_t r = 0; r < rings_.size(); ++r) {
    const Ring& ring = rings_[r];
    std::vector<double> lengths = {0.0};
    for (std::size_t i = 0; i < ring.size(); ++i) {
      lengths.push_back(lengths.back() + (ring[(i + 1) % ring.size()] - ring[i]).norm());
      starts.push_back(ring[i]);
      ends.push_back(ring[(i + 1) % ring.size()]);
      boundary_edges_.push_back({r, i});
    }
    arc_lengths_.push_back(std::move(lengths));
  }
  if (!starts.empty()) boundary_index_.emplace(std::move(starts), std::move(ends));
  for (const PolygonWithHoles& part : patch_areas_) part_boxes_.push_back(boundingBox(part.hull));
}

UnseenAreaRepair::RingPosition UnseenAreaRepair::nearestOnBoundary(const Point2& p,
                                                                   double* distance) const {
  *distance = std::numeric_limits<double>::infinity();
  if (!boundary_index_) return {};
  const NearestSegmentIndex::Nearest nearest = boundary_index_->nearest(p);
  const auto [ring, edge] = boundary_edges_[nearest.segment];
  const Point2& a = rings_[ring][edge];
  const Point2 q = closestPointOnSegment(p, a, rings_[ring][(edge + 1) % rings_[ring].size()]);
  *distance = nearest.distance;
  return {ring, edge, arc_lengths_[ring][edge] + (q - a).norm()};
}

bool UnseenAreaRepair::inPatchAreas(const Point2& p) const {
  for (std::size_t i = 0; i < patch_areas_.size(); ++i) {
    if (part_boxes_[i].contains(p) && contains(patch_areas_[i], p)) return true;
  }
  return false;
}

Point2 UnseenAreaRepair::pointAt(std::size_t ring, double arc_length) const {
  const std::vector<double>& lengths = arc_lengths_[ring];
  const Ring& vertices = rings_[ring];
  const double perimeter = lengths.back();
  double s = std::fmod(arc_length, perimeter);
  if (s < 0.0) s += perimeter;
  const std::size_t i = static_cast<std::size_t>(std::min<std::ptrdiff_t>(
      std::upper_bound(lengths.begin(), lengths.end(), s) - lengths.begin() - 1,
      static_cast<std::ptrdiff_t>(vertices.size()) - 1));
  const Point2& a = vertices[i];
  const Point2& b = vertices[(i + 1) % vertices.size()];
  const double edge = lengths[i + 1] - lengths[i];
  const double t = edge > 0.0 ? std::clamp((s - lengths[i]) / edge, 0.0, 1.0) : 0.0;
  return a + t * (b - a);
}

std::vector<Point2> UnseenAreaRepair::boundaryWalk(std::size_t ring, double from, double to) const {
  const std::vector<double>& lengths = arc_lengths_[ring];
  const double perimeter = lengths.back();
  if (to < from) to += perimeter;
  std::vector<Point2> walk = {pointAt(ring, from)};
  // The ring's vertices strictly between, over at most one round.
  for (int round = 0; round < 2; ++round) {
    for (std::size_t i = 0; i < rings_[ring].size(); ++i) {
      const double s = lengths[i] + round * perimeter;
      if (s > from && s < to) walk.push_back(rings_[ring][i]);
    }
  }
  walk.push_back(pointAt(ring, to));
  walk.erase(std::unique(walk.begin(), walk.end()), walk.end());
  return walk;
}

std::vector<std::vector<Point2>> UnseenAreaRepair::patchesFor(
    const std::vector<Point2>& samples) const {
  const double boundary_reach = kBoundaryReachShare * sensor_.width();
  std::vector<Point2> deep;
  std::vector<BoundarySample> beyond;
  std::vector<std::vector<double>> along_ring(rings_.size());
  for (const Point2& sample : samples) {
    double distance = 0.0;
    const RingPosition position = nearestOnBoundary(sample, &distance);
    const bool inside = inPatchAreas(sample);
    if (inside && distance > boundary_reach) {
      deep.push_back(sample);
    } else if (inside) {
      along_ring[position.ring].push_back(position.arc_length);
    } else {
      beyond.push_back({sample, position, distance});
    }
  }
  std::vector<std::vector<Point2>> patches = excursionPatches(&beyond);
  for (const BoundarySample& sample : beyond) {
    along_ring[sample.position.ring].push_back(sample.position.arc_length);
  }
  // Along each ring: the stretches that hold the region's boundary points, split where
  // they lie far apart (the arc lengths are circular: the largest gap may wrap).
  const double split = kPatchSplitShare * sensor_.width();
  for (std::size_t r = 0; r < rings_.size(); ++r) {
    std::vector<double>& s = along_ring[r];
    if (s.empty()) continue;
    std::sort(s.begin(), s.end());
    const double perimeter = arc_lengths_[r].back();
    std::size_t widest = s.size() - 1;  // the gap after s[widest], wrapping at the end
    double widest_gap = s.front() + perimeter - s.back();
    for (std::size_t i = 0; i + 1 < s.size(); ++i) {
      if (s[i + 1] - s[i] > widest_gap) {
        widest_gap = s[i + 1] - s[i];
        widest = i;
      }
    }
    // Walk from the point after the widest gap round to the one before it.
    std::size_t begin = (widest + 1) % s.size();
    double from = s[begin];
    double previous = from;
    for (std::size_t k = 1; k <= s.size(); ++k) {
      const std::size_t i = (begin + k) % s.size();
      double gap = k == s.size() ? std::numeric_limits<double>::infinity() : s[i] - previous;
      if (gap < 0.0) gap += perimeter;
      if (gap > split) {
        patches.push_back(boundaryWalk(r, from, previous));
        from = s[i];
      }
      previous = s[i];
    }
  }
  // Deeper inside: one patch along the cells' main axis, between its extreme cells.
  if (!deep.empty()) {
    Point2 centroid = Point2::Zero();
    for (const Point2& p : deep) centroid += p;
    centroid /= static_cast<double>(deep.size());
    double xx = 0.0, xy = 0.0, yy = 0.0;
    for (const Point2& p : deep) {
      const Point2 d = p - centroid;
      xx += d.x() * d.x();
      xy += d.x() * d.y();
      yy += d.y() * d.y();
    }
    const double angle = 0.5 * std::atan2(2.0 * xy, xx - yy);
    const Point2 axis(std::cos(angle), std::sin(angle));
    const auto by_axis = [&](const Point2& a, const Point2& b) {
      return a.dot(axis) < b.dot(axis);
    };
    const Point2 low = *std::min_element(deep.begin(), deep.end(), by_axis);
    const Point2 high = *std::max_element(deep.begin(), deep.end(), by_axis);
    patches.push_back(graph_.shortestPath(low, high));
  }
  return patches;
}

std::vector<std::vector<Point2>> UnseenAreaRepair::excursionPatches(
    std::vector<BoundarySample>* beyond) const {
  struct Excursion {
    Point2 corner;
    std::vector<Point2> way;  ///< the far ends of its legs, the last its apex
    bool sees = false;

    double distanceTo(const Point2& p) const {
      double d = distanceToSegment(p, corner, way.front());
      for (std::size_t i = 1; i < way.size(); ++i) {
        d = std::min(d, distanceToSegment(p, way[i - 1], way[i]));
      }
      return d;
    }
  };
  // The excursions from the corners of the edges beside the samples.
  std::vector<Excursion> candidates;
  std::set<std::pair<std::size_t, std::size_t>> tried;  // ring, vertex
  for (const BoundarySample& sample : *beyond) {
    const Ring& ring = rings_[sample.position.ring];
    const std::size_t n = ring.size();
    for (const std::size_t v : {sample.position.edge, (sample.position.edge + 1) % n}) {
      if (!tried.insert({sample.position.ring, v}).second) continue;
      if (const std::optional<Point2> apex =
              excursions_.apex(ring[(v + n - 1) % n], ring[v], ring[(v + 1) % n])) {
        candidates.push_back({ring[v], {*apex}});
      }
    }
  }
  // The excursion that passes nearest to a sample, nearer than the boundary; none else.
  const auto nearestTo = [&](const BoundarySample& sample) {
    Excursion* nearest = nullptr;
    double nearest_distance = sample.distance;
    for (Excursion& excursion : candidates) {
      const double d = excursion.distanceTo(sample.point);
      if (d < nearest_distance) {
        nearest = &excursion;
        nearest_distance = d;
      }
    }
    return std::make_pair(nearest, nearest_distance);
  };
  // And toward the samples farthest from the boundary that no excursion passes near (a
  // slot's mouth, where the boundary runs straight past the exact offset's bulge), on
  // into a funnel that the walls bend.
  const double boundary_reach = kBoundaryReachShare * sensor_.width();
  for (int k = 0; k < kDeepExcursions; ++k) {
    const BoundarySample* deepest = nullptr;
    double depth = boundary_reach;
    for (const BoundarySample& sample : *beyond) {
      const double nearest = nearestTo(sample).second;
      if (nearest > depth) {
        depth = nearest;
        deepest = &sample;
      }
    }
    if (deepest == nullptr) break;
    const Point2 from = pointAt(deepest->position.ring, deepest->position.arc_length);
    std::vector<Point2> way = excursions_.walk(from, deepest->point, boundary_reach);
    if (way.empty()) break;
    candidates.push_back({from, std::move(way)});
  }
  // The samples an excursion sees leave `beyond`.
  beyond->erase(std::remove_if(beyond->begin(), beyond->end(),
                               [&](const BoundarySample& sample) {
                                 Excursion* nearest = nearestTo(sample).first;
                                 if (nearest != nullptr) nearest->sees = true;
                                 return nearest != nullptr;
                               }),
                beyond->end());
  std::vector<std::vector<Point2>> patches;
  for (const Excursion& excursion : candidates) {
    if (!excursion.sees) continue;
    // Out along its legs and back.
    std::vector<Point2> patch = {excursion.corner};
    patch.insert(patch.end(), excursion.way.begin(), excursion.way.end());
    patch.insert(patch.end(), std::next(excursion.way.rbegin()), excursion.way.rend());
    patch.push_back(excursion.corner);
    patches.push_back(std::move(patch));
  }
  return patches;
}

bool UnseenAreaRepair::legNeeded(const SeenArea& seen, const Point2& a, const Point2& b) const {
  const double end_reach = 0.5 * std::hypot(sensor_.width(), sensor_.length());
  const double length = (b - a).norm();
  if (length <= 2.0 * end_reach) return true;
  const Point2 along = (b - a) / length;
  const Point2 across(-along.y(), along.x());
  const CellMask& reachable = evaluator_.reachableArea();
  for (int k = 0; k <= kLegSamplesAlong; ++k) {
    const double s = end_reach + (length - 2.0 * end_reach) * k / kLegSamplesAlong;
    for (int j = -kLegSamplesAcross; j <= kLegSamplesAcross; ++j) {
      const double u = kLegSampleReach * 0.5 * sensor_.width() * j / kLegSamplesAcross;
      const std::optional<std::size_t> cell = evaluator_.cellAt(a + s * along + u * across);
      if (cell && reachable[*cell] != 0 && seen.visits(*cell) < 2) return true;
    }
  }
  return false;
}

std::vector<std::size_t> UnseenAreaRepair::nearestLegs(const std::vector<Point2>& patch,
                                                       const std::vector<Point2>& path,
                                                       std::size_t first_inside,
                                                       std::size_t last_inside) const {
  std::vector<std::pair<double, std::size_t>> legs;
  for (std::size_t i = first_inside; i < last_inside; ++i) {
    if (!graph_.boundary().contains(path[i]) || !graph_.boundary().contains(path[i + 1])) continue;
    const double near = std::min(distanceToSegment(patch.front(), path[i], path[i + 1]),
                                 distanceToSegment(patch.back(), path[i], path[i + 1]));
    legs.emplace_back(near, i);
  }
  const std::size_t count = std::min(kCandidateLegs, legs.size());
  std::partial_sort(legs.begin(), legs.begin() + static_cast<std::ptrdiff_t>(count), legs.end());
  std::vector<std::size_t> nearest;
  for (std::size_t k = 0; k < count; ++k) nearest.push_back(legs[k].second);
  return nearest;
}

std::optional<UnseenAreaRepair::Bump> UnseenAreaRepair::bump(const Point2& apex, const Point2& a,
                                                             const Point2& b) const {
  const double length = (b - a).norm();
  if (length <= kLengthTolerance) return std::nullopt;
  const Point2 along = (b - a) / length;
  const double at = std::clamp((apex - a).dot(along), 0.0, length);
  const double height = (apex - (a + at * along)).norm();
  if (height <= kLengthTolerance) return std::nullopt;
  for (const double spread : kBumpSpreads) {
    const Point2 leave = a + std::max(0.0, at - spread * height) * along;
    const Point2 rejoin = a + std::min(length, at + spread * height) * along;
    if (excursions_.keepsDistance(leave, apex) && excursions_.keepsDistance(apex, rejoin)) {
      return Bump{segment_cost_.pathCost({a, leave, apex, rejoin, b}) - segment_cost_.of(a, b),
                  leave, rejoin};
    }
  }
  return std::nullopt;
}

UnseenAreaRepair::Insertion UnseenAreaRepair::cheapestInsertion(
    const std::vector<Point2>& patch, LegReplacement replacement, const SeenArea& view,
    const std::vector<std::size_t>& legs, const std::vector<Point2>& path,
    VisibilityGraph::PointCache* routes) const {
  // A spur: from an anchor on the path out to the patch, along it and back, the path's
  // own legs kept (they see what the sweeps rely on). The anchor is a waypoint, or the
  // point of a leg nearest to the patch, which splits the leg. A leg may instead be
  // replaced by a detour through the patch: any leg, or only one whose middle shows nothing
  // that no other step of the path saw in `view` (a transition over swept area). An
  // excursion may also bend a leg out through its far end (not when every leg must be
  // kept: the bent middle sees less of what the leg saw).
  const BoundaryGrid& area = graph_.boundary();
  const double patch_cost = segment_cost_.pathCost(patch);
  const bool excursion = patch.size() == 3 && patch.front() == patch.back();
  Insertion best;
  for (const std::size_t i : legs) {
    if (excursion && replacement != LegReplacement::kNone) {
      const std::optional<Bump> bent = bump(patch[1], path[i], path[i + 1]);
      if (bent && bent->cost < best.cost)
        best = Insertion{bent->cost, i, std::nullopt, false, bent};
    }
    const double leg_cost = segment_cost_.of(path[i], path[i + 1]);
    for (bool reversed : {false, true}) {
      const Point2& in = reversed ? patch.back() : patch.front();
      const Point2& out = reversed ? patch.front() : patch.back();
      const auto consider = [&](double cost, std::optional<Point2> anchor) {
        if (cost < best.cost) best = Insertion{cost, i, anchor, reversed, std::nullopt};
      };
      for (const Point2& anchor :
           {path[i], path[i + 1], closestPointOnSegment(in, path[i], path[i + 1])}) {
        if (!area.contains(anchor)) continue;
        const double split =
            segment_cost_.of(path[i], anchor) + segment_cost_.of(anchor, path[i + 1]) - leg_cost;
        consider(
            split + graph_.cost(anchor, in, routes) + patch_cost + graph_.cost(out, anchor, routes),
            anchor);
      }
      if (replacement == LegReplacement::kAnyLeg ||
          (replacement == LegReplacement::kUnneededLeg && !legNeeded(view, path[i], path[i + 1]))) {
        consider(graph_.cost(path[i], in, routes) + patch_cost +
                     graph_.cost(out, path[i + 1], routes) - leg_cost,
                 std::nullopt);
      }
    }
  }
  return best;
}

std::vector<Point2> UnseenAreaRepair::insertedPoints(const Insertion& insertion,
                                                     const std::vector<Point2>& patch,
                                                     const std::vector<Point2>& path,
                                                     VisibilityGraph::PointCache* routes) const {
  const Point2& first = path[insertion.leg];
  const Point2& second = path[insertion.leg + 1];
  std::vector<Point2> inserted;
  if (insertion.bump) {
    if (insertion.bump->leave != first) inserted.push_back(insertion.bump->leave);
    inserted.push_back(patch[1]);
    if (insertion.bump->rejoin != second) inserted.push_back(insertion.bump->rejoin);
    return inserted;
  }
  std::vector<Point2> stretch = patch;
  if (insertion.reversed) std::reverse(stretch.begin(), stretch.end());
  // From where the detour leaves the path to where it rejoins it, without repeated points.
  const Point2& leave = insertion.anchor ? *insertion.anchor : first;
  const Point2& rejoin = insertion.anchor ? *insertion.anchor : second;
  std::vector<Point2> detour = graph_.shortestPath(leave, stretch.front(), routes);
  detour.insert(detour.end(), stretch.begin() + 1, stretch.end());
  const std::vector<Point2> back = graph_.shortestPath(stretch.back(), rejoin, routes);
  detour.insert(detour.end(), back.begin() + 1, back.end());
  detour.erase(std::unique(detour.begin(), detour.end()), detour.end());
  if (insertion.anchor) {
    if (detour.size() <= 1) return {};  // the patch is the anchor
    // After the leg's first waypoint: the anchor (unless it is that waypoint), the spur,
    // and the anchor again (unless it is the leg's second waypoint).
    if (*insertion.anchor != first) inserted.push_back(*insertion.anchor);
    inserted.insert(inserted.end(), detour.begin() + 1, detour.end());
    if (*insertion.anchor == second) inserted.pop_back();
  } else if (detour.size() > 2) {  // else the patch lies on the leg's ends
    inserted.assign(detour.begin() + 1, detour.end() - 1);
  }
  return inserted;
}

bool UnseenAreaRepair::insert(const std::vector<Point2>& patch, LegReplacement replacement,
                              const SeenArea& view, std::size_t first_inside,
                              std::size_t* last_inside, std::vector<Point2>* waypoints,
                              VisibilityGraph::PointCache* routes) const {
  std::vector<Point2>& path = *waypoints;
  // A patch is driven from and back to the area the graph routes in.
  const BoundaryGrid& area = graph_.boundary();
  if (!area.contains(patch.front()) || !area.contains(patch.back())) return false;
  const std::vector<std::size_t> legs = nearestLegs(patch, path, first_inside, *last_inside);
  if (legs.empty()) return false;
  const Insertion best = cheapestInsertion(patch, replacement, view, legs, path, routes);
  if (!std::isfinite(best.cost)) return false;
  const std::vector<Point2> inserted = insertedPoints(best, patch, path, routes);
  if (inserted.empty()) return false;
  path.insert(path.begin() + static_cast<std::ptrdiff_t>(best.leg) + 1, inserted.begin(),
              inserted.end());
  *last_inside += inserted.size();
  return true;
}

RepairedPath UnseenAreaRepair::repair(std::vector<Point2> waypoints, std::size_t first_inside,
                                      std::size_t last_inside) const {
  return repair(unseen(waypoints), first_inside, last_inside);
}

RepairedPath UnseenAreaRepair::repair(Unseen measured, std::size_t first_inside,
                                      std::size_t last_inside) const {
  const double cell_area = evaluator_.raster().cellArea();
  const CellMask& reachable = evaluator_.reachableArea();
  RepairedPath result;
  result.reachable_m2 = static_cast<double>(CoverageRaster::countCells(reachable)) * cell_area;
  std::vector<Point2> waypoints = std::move(measured.waypoints);
  SeenArea seen = std::move(*measured.seen);
  std::vector<UnseenRegion> regions = std::move(measured.regions);
  result.unseen_before_m2 = totalArea(regions);
  double unseen = result.unseen_before_m2;
  VisibilityGraph::PointCache routes;
  for (int round = 0; round < kRepairRounds; ++round) {
    // First with any leg replaced where that is cheaper, then only legs whose view others
    // have: the first that loses no more of what the path saw than a sliver (a replaced leg
    // may have been a lane) and sees more; else spurs only, which keep every leg, so what
    // they lose is the raster's sampling of the legs they split: taken when they see more.
    bool accepted = false;
    for (const LegReplacement replacement :
         {LegReplacement::kAnyLeg, LegReplacement::kUnneededLeg, LegReplacement::kNone}) {
      std::vector<Point2> patched = waypoints;
      std::size_t patched_last = last_inside;
      std::size_t patches = 0;
      for (const UnseenRegion& region : regions) {
        if (region.area_m2 < min_region_m2_) break;  // the largest first
        for (const std::vector<Point2>& patch : patchesFor(region.samples)) {
          if (isDrivenExcursion(patch, patched)) continue;
          if (insert(patch, replacement, seen, first_inside, &patched_last, &patched, &routes)) {
            ++patches;
          }
        }
      }
      if (patches == 0) break;
      SeenArea patched_seen = evaluator_.seeWaypointPath(legHeadingPoses(patched));
      std::size_t lost = 0;
      for (std::size_t i = 0; i < reachable.size(); ++i) {
        if (reachable[i] != 0 && seen.seen(i) && !patched_seen.seen(i)) ++lost;
      }
      std::vector<UnseenRegion> left =
          evaluator_.unseenRegions(patched_seen, kSamplesPerRegion, join_distance_);
      const double patched_unseen = totalArea(left);
      const bool keeps_every_leg = replacement == LegReplacement::kNone;
      if ((!keeps_every_leg && static_cast<double>(lost) * cell_area > min_region_m2_) ||
          patched_unseen >= unseen - min_region_m2_) {
        continue;  // the patches lost more than they saw, or saw nothing worth their cost
      }
      waypoints = std::move(patched);
      last_inside = patched_last;
      result.patches += patches;
      seen = std::move(patched_seen);
      regions = std::move(left);
      unseen = patched_unseen;
      accepted = true;
      break;
    }
    if (!accepted) break;
  }
  result.waypoints = std::move(waypoints);
  result.last_inside = last_inside;
  result.unseen_after_m2 = unseen;
  return result;
}

UnseenAreaRepair::Unseen UnseenAreaRepair::unseen(const std::vector<Point2>& waypoints) const {
  Unseen result;
  result.waypoints = waypoints;
  result.seen = evaluator_.seeWaypointPath(legHeadingPoses(waypoints));
  result.regions = evaluator_.unseenRegions(*result.seen, kSamplesPerRegion, join_distance_);
  for (const UnseenRegion& region : result.regions) {
    result.area_m2 += region.area_m2;
    if (region.area_m2 < min_region_m2_) continue;
    result.samples.insert(result.samples.end(), region.samples.begin(), region.samples.end());
  }
  return result;
}

}  // namespace kinematic_coverage::core
