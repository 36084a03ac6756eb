#include "polygon_coverage_ros_bridge/route/offset_part_joiner.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/geometry/region_intersection.h"
#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"
#include "polygon_coverage_ros_bridge/route/segment_cost.h"
#include "polygon_coverage_ros_bridge/route/visibility_graph.h"

namespace kinematic_coverage::core {
namespace {

/// Passages narrower than this share of the wall distance are not searched for (unless the
/// gap clearance is smaller): pinch points, which no widest passage names and offsets at
/// smaller distances would find only at a cost.
constexpr double kMinClearanceShare = 0.02;
/// A bracket of offset distances in which the parts' grouping changes is halved this many
/// times: the gap's clearance is found to about 0.1 % of the wall distance, with about 10
/// offsets per gap (milliseconds each); the transit, the shortest path in the offset at that
/// distance, runs that close to the gap's middle.
constexpr int kRefinementDepth = 10;
/// Half-width of a transit corridor, as a share of its path's clearance: the corridor
/// stays inside the free area, and a transit in it keeps 86 % of the path's clearance
/// (the corridor's corners lie at sqrt(2) half-widths from the path); narrower where the
/// transit must keep the gap clearance (corridorHalfWidth).
constexpr double kCorridorShare = 0.1;
/// Rounding of the Boolean operations' results, relative to the map's scale.
constexpr double kRelativeVertexTolerance = 1e-9;
/// Free areas with more vertices than this are joined in windows first: a gap's path in an
/// offset of the whole area may need a visibility graph of the whole lake there (seconds),
/// while most gaps are short straits beside their parts.
constexpr std::size_t kWindowedJoinVertices = 2000;
/// A part's window reaches this many wall distances beyond its bounding box (a strait up
/// to about 6 wall distances long is found in it; a longer one on the whole area); the
/// other parts are sampled 2 wall distances less far, so the window's own edges (which
/// the offsets move inward by at most a wall distance) never touch what is compared.
constexpr double kWindowMarginShare = 10.0;
constexpr double kSampleMarginShare = 8.0;
/// A gap's path is first sought within these many times the distance between its ends
/// around them (pathBetweenParts).
constexpr double kPathWindowShares[] = {2.0, 8.0};

/// Boundary vertices standing for one part in a joining problem; the first tells which
/// offset component holds the part.
using PartVertices = std::vector<Point2>;

/// The offset free area at one distance and the component each part falls into.
struct Level {
  double distance = 0.0;
  std::vector<PolygonWithHoles> components;
  std::vector<int> component_of_part;  ///< -1: the part lies in no component
};

/// The parts' grouping in the offset at `distance` with `corners`.
Level levelAt(const WallOffset& offset, const std::vector<PartVertices>& parts, double distance,
              OffsetCorners corners = OffsetCorners::kMitred) {
  Level level;
  level.distance = distance;
  level.components = offset.at(distance, corners).parts;
  const double tolerance = corners == OffsetCorners::kMitred ? 0.0 : kRoundOffsetReach;
  for (const PartVertices& part : parts) {
    // A part lies inside the offset at a smaller distance (offsets are nested; a vertex on
    // the part's boundary at most the round offset's shortfall outside it), so one of its
    // vertices tells which component holds it.
    int found = -1;
    for (std::size_t c = 0; c < level.components.size() && found < 0; ++c) {
      if (contains(level.components[c], part.front(), tolerance)) {
        found = static_cast<int>(c);
      }
    }
    level.component_of_part.push_back(found);
  }
  return level;
}

/// The grouping of the parts as labels numbered by first occurrence, to compare levels.
std::vector<int> grouping(const Level& level) {
  std::map<int, int> label;
  std::vector<int> result;
  for (std::size_t i = 0; i < level.component_of_part.size(); ++i) {
    const int component = level.component_of_part[i];
    const int key = component < 0 ? -1 - static_cast<int>(i) : component;
    result.push_back(label.emplace(key, static_cast<int>(label.size())).first->second);
  }
  return result;
}

/// A bracket of distances: parts apart at `upper` share a component at `lower`.
struct Merge {
  Level lower;
  std::vector<int> upper_groups;
};

/// Halves [lower, upper] where the grouping changes, down to kRefinementDepth, collecting
/// the brackets of every change, largest distances first.
void refine(const WallOffset& offset, const std::vector<PartVertices>& parts, const Level& lower,
            const Level& upper, int depth, std::vector<Merge>* merges) {
  const std::vector<int> lower_groups = grouping(lower);
  const std::vector<int> upper_groups = grouping(upper);
  if (lower_groups == upper_groups) return;
  if (depth == 0) {
    merges->push_back({lower, upper_groups});
    return;
  }
  const Level middle = levelAt(offset, parts, 0.5 * (lower.distance + upper.distance));
  refine(offset, parts, middle, upper, depth - 1, merges);
  refine(offset, parts, lower, middle, depth - 1, merges);
}

/// The closest pair of vertices, one of the parts in `from`, one of those in `to`.
std::pair<Point2, Point2> closestVertices(const std::vector<PartVertices>& parts,
                                          const std::vector<std::size_t>& from,
                                          const std::vector<std::size_t>& to,
                                          std::size_t* from_part, std::size_t* to_part) {
  double best = std::numeric_limits<double>::infinity();
  std::pair<Point2, Point2> result;
  for (std::size_t i : from) {
    for (std::size_t j : to) {
      for (const Point2& q : parts[j]) {
        for (const Point2& p : parts[i]) {
          const double d = (p - q).squaredNorm();
          if (d < best) {
            best = d;
            result = {p, q};
            *from_part = i;
            *to_part = j;
          }
        }
      }
    }
  }
  return result;
}

/// The least distance from the path to the free area's boundary and where it is.
std::pair<double, Point2> pathClearance(const PolygonWithHoles& free_area,
                                        const std::vector<Point2>& path) {
  // The nearest vertex to the path's first point bounds the clearance from above (that point
  // reaches it): edges whose box lies at least that far from the path's box are skipped.
  double least = std::numeric_limits<double>::infinity();
  auto nearest = [&](const Ring& ring) {
    for (const Point2& v : ring) least = std::min(least, (v - path.front()).norm());
  };
  nearest(free_area.hull);
  for (const Ring& hole : free_area.holes) nearest(hole);
  const Eigen::AlignedBox2d path_box = boundingBox(path);
  Point2 where = path.front();
  auto visit = [&](const Ring& ring) {
    for (std::size_t e = 0, n = ring.size(); e < n; ++e) {
      const Point2& c = ring[e];
      const Point2& d = ring[(e + 1) % n];
      const Eigen::AlignedBox2d edge_box(c.cwiseMin(d), c.cwiseMax(d));
      if (path_box.exteriorDistance(edge_box) >= least) continue;
      for (std::size_t s = 0; s + 1 < path.size(); ++s) {
        const Point2& a = path[s];
        const Point2& b = path[s + 1];
        for (const Point2& p : {a, b}) {
          const double distance = distanceToSegment(p, c, d);
          if (distance < least) {
            least = distance;
            where = p;
          }
        }
        for (const Point2& p : {c, d}) {
          const double distance = distanceToSegment(p, a, b);
          if (distance < least) {
            least = distance;
            where = closestPointOnSegment(p, a, b);
          }
        }
      }
    }
  };
  visit(free_area.hull);
  for (const Ring& hole : free_area.holes) visit(hole);
  return {least, where};
}

/// Rectangles of half-width `half_width` around every segment of the path, each reaching
/// `half_width` past its ends so that consecutive ones overlap at the bends.
std::vector<PolygonWithHoles> corridor(const std::vector<Point2>& path, double half_width) {
  std::vector<PolygonWithHoles> pieces;
  for (std::size_t s = 0; s + 1 < path.size(); ++s) {
    const Point2 along = path[s + 1] - path[s];
    const double length = along.norm();
    if (length <= 0.0) continue;
    const Point2 u = along / length * half_width;
    const Point2 n(-u.y(), u.x());
    pieces.push_back(
        {{path[s] - u - n, path[s + 1] + u - n, path[s + 1] + u + n, path[s] - u + n}, {}});
  }
  return pieces;
}

/// Which parts are joined already, as a union-find over the parts.
class PartGroups {
 public:
  explicit PartGroups(std::size_t count) : root_(count) {
    for (std::size_t k = 0; k < count; ++k) root_[k] = k;
  }
  std::size_t find(std::size_t k) {
    while (root_[k] != k) k = root_[k] = root_[root_[k]];
    return k;
  }
  /// Joins the group of `to` to the group of `from`.
  void join(std::size_t from, std::size_t to) { root_[find(to)] = find(from); }

 private:
  std::vector<std::size_t> root_;
};

/// The hull's vertices, then the holes'.
PartVertices verticesOf(const PolygonWithHoles& part) {
  PartVertices result = part.hull;
  for (const Ring& hole : part.holes) result.insert(result.end(), hole.begin(), hole.end());
  return result;
}

/// The shortest path from a to b inside `area`: straight when the segment stays inside (no
/// visibility graph is built then, which on a whole lake costs seconds).
std::vector<Point2> shortestPathInside(const PolygonWithHoles& area, const Point2& a,
                                       const Point2& b) {
  if (a == b) return {a};
  const BoundaryGrid grid(area);
  if (grid.contains(a) && grid.contains(b) && grid.segmentInside(a, b)) return {a, b};
  const SegmentCost distance_cost(CostFunction::kDistance, VehicleLimits{});
  return VisibilityGraph(area, distance_cost).shortestPath(a, b);
}

/// The axis-aligned bounds of `ring` with `margin` on every side.
Eigen::AlignedBox2d boxAround(const Ring& ring, double margin) {
  const Eigen::AlignedBox2d bounds = boundingBox(ring);
  const Point2 grow = Point2::Constant(margin);
  return {bounds.min() - grow, bounds.max() + grow};
}

/// The point of the area's boundary nearest to p.
Point2 nearestBoundaryPoint(const PolygonWithHoles& area, const Point2& p) {
  Point2 nearest = p;
  double least = std::numeric_limits<double>::infinity();
  const auto visit = [&](const Ring& ring) {
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      const Point2 q = closestPointOnSegment(p, ring[i], ring[(i + 1) % n]);
      if ((q - p).norm() < least) {
        least = (q - p).norm();
        nearest = q;
      }
    }
  };
  visit(area.hull);
  for (const Ring& hole : area.holes) visit(hole);
  return nearest;
}

/// The shortest path inside the offset component `area` between vertices a and b of two
/// parts, which may lie up to kRoundOffsetReach outside it: from each of them to the
/// component's nearest boundary point when it does. The path is sought first in the part
/// of the component within boxes around a and b (kPathWindowShares times their distance
/// beyond them): a round component has arcs of many vertices at every corner, and a
/// visibility graph of all of them costs seconds where the gap's neighbourhood costs
/// milliseconds.
std::vector<Point2> pathBetweenParts(const PolygonWithHoles& area, const Point2& a,
                                     const Point2& b) {
  const Point2 from = contains(area, a) ? a : nearestBoundaryPoint(area, a);
  const Point2 to = contains(area, b) ? b : nearestBoundaryPoint(area, b);
  std::vector<Point2> path;
  for (const double share : kPathWindowShares) {
    const Eigen::AlignedBox2d box = boxAround({from, to}, share * (to - from).norm());
    for (const PolygonWithHoles& piece : clipToBox(area, box.min(), box.max())) {
      if (path.empty() && contains(piece, from, kRoundOffsetReach) &&
          contains(piece, to, kRoundOffsetReach)) {
        path = shortestPathInside(piece, from, to);
      }
    }
    if (!path.empty()) break;
  }
  if (path.empty()) path = shortestPathInside(area, from, to);
  if (from != a) path.insert(path.begin(), a);
  if (to != b) path.push_back(b);
  return path;
}

/// The distances that bound the search for gaps, below the wall distance: a gap found at
/// `passable` or above keeps the gap clearance within kClearanceTolerance (its path lies in
/// that offset), one found below it is narrower; none is sought below `lowest`.
struct SearchLevels {
  double lowest = 0.0;
  double passable = 0.0;
};

SearchLevels searchLevels(double wall_distance, double gap_clearance) {
  SearchLevels levels;
  levels.passable = std::max(gap_clearance - 0.5 * kClearanceTolerance, 0.75 * gap_clearance);
  levels.lowest = std::min(kMinClearanceShare * wall_distance, 0.5 * levels.passable);
  return levels;
}

/// The gaps that join the parts of `area`'s offset at decreasing distances, largest
/// clearance first. `parts[k]` stands for part `owner[k]` of `part_count` (a part may be
/// sampled in several pieces); the gaps name the owners, and each joins two groups that
/// no earlier gap joined. Clearances are measured against `free_area`.
std::vector<OffsetGap> gapsIn(const PolygonWithHoles& area, const std::vector<PartVertices>& parts,
                              const std::vector<std::size_t>& owner, std::size_t part_count,
                              double wall_distance, const SearchLevels& levels,
                              const PolygonWithHoles& free_area) {
  Level upper;
  upper.distance = wall_distance;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    upper.component_of_part.push_back(static_cast<int>(owner[k]));
  }
  // Every level is an offset of the same area: its rings converted once.
  const WallOffset offset(area);
  const Level lowest = levelAt(offset, parts, levels.lowest);
  const Level passable = levelAt(offset, parts, levels.passable);
  std::vector<Merge> merges;
  refine(offset, parts, passable, upper, kRefinementDepth, &merges);
  // The mitred offsets find the gaps fast, but their corners close necks that the points at
  // least the passable distance from the walls pass: the parts that the exact offset there
  // joins (kRoundClear) are joined before narrower gaps are sought.
  merges.push_back(
      {levelAt(offset, parts, levels.passable, OffsetCorners::kRoundClear), grouping(passable)});
  refine(offset, parts, lowest, passable, kRefinementDepth, &merges);

  PartGroups groups(part_count);
  std::vector<OffsetGap> gaps;
  for (const Merge& merge : merges) {
    for (std::size_t c = 0; c < merge.lower.components.size(); ++c) {
      // The groups (at the merge's upper distance) that this component holds.
      std::map<std::size_t, std::vector<std::size_t>> held;
      for (std::size_t k = 0; k < parts.size(); ++k) {
        if (merge.lower.component_of_part[k] == static_cast<int>(c)) {
          held[groups.find(owner[k])].push_back(k);
        }
      }
      if (held.size() <= 1) continue;
      std::vector<std::size_t> joined = held.begin()->second;
      for (auto it = std::next(held.begin()); it != held.end(); ++it) {
        std::size_t from = 0;
        std::size_t to = 0;
        const auto [a, b] = closestVertices(parts, joined, it->second, &from, &to);
        OffsetGap gap;
        gap.from_part = owner[from];
        gap.to_part = owner[to];
        gap.path = pathBetweenParts(merge.lower.components[c], a, b);
        std::tie(gap.clearance_m, gap.narrowest_point) = pathClearance(free_area, gap.path);
        groups.join(gap.from_part, gap.to_part);
        joined.insert(joined.end(), it->second.begin(), it->second.end());
        gaps.push_back(std::move(gap));
      }
    }
  }
  return gaps;
}

/// gapsIn run in a window around every part but the largest: the free area clipped to the
/// part's bounds and kWindowMarginShare wall distances, the other parts sampled where they
/// come within kSampleMarginShare wall distances. A gap that the window finds is a path in
/// the free area whose clearance is measured exactly; a part the windows leave apart from
/// the others is for the caller to join on the whole area.
std::vector<OffsetGap> windowedGaps(const PolygonWithHoles& free_area,
                                    const std::vector<PolygonWithHoles>& parts,
                                    double wall_distance, const SearchLevels& levels) {
  std::vector<OffsetGap> gaps;
  for (std::size_t k = 1; k < parts.size(); ++k) {
    const Eigen::AlignedBox2d window = boxAround(parts[k].hull, kWindowMarginShare * wall_distance);
    const Eigen::AlignedBox2d sample = boxAround(parts[k].hull, kSampleMarginShare * wall_distance);
    PolygonWithHoles nearby{free_area.hull, {}};
    for (const Ring& hole : free_area.holes) {
      if (boundingBox(hole).intersects(window)) nearby.holes.push_back(hole);
    }
    const PolygonWithHoles* area = nullptr;
    const std::vector<PolygonWithHoles> pieces = clipToBox(nearby, window.min(), window.max());
    for (const PolygonWithHoles& piece : pieces) {
      if (contains(piece, parts[k].hull.front())) area = &piece;
    }
    if (area == nullptr) continue;
    std::vector<PartVertices> local = {verticesOf(parts[k])};
    std::vector<std::size_t> owner = {k};
    for (std::size_t j = 0; j < parts.size(); ++j) {
      if (j == k || !boundingBox(parts[j].hull).intersects(sample)) continue;
      for (const PolygonWithHoles& clipped : clipToBox(parts[j], sample.min(), sample.max())) {
        local.push_back(verticesOf(clipped));
        owner.push_back(j);
      }
    }
    const std::vector<OffsetGap> found =
        gapsIn(*area, local, owner, parts.size(), wall_distance, levels, free_area);
    gaps.insert(gaps.end(), found.begin(), found.end());
  }
  return gaps;
}

std::size_t vertexCount(const PolygonWithHoles& area) {
  std::size_t count = area.hull.size();
  for (const Ring& hole : area.holes) count += hole.size();
  return count;
}

/// The gaps widest first, without those that join parts an earlier (wider) gap joined
/// already: a widest spanning forest of the parts (Kruskal's order).
std::vector<OffsetGap> widestFirst(std::vector<OffsetGap> gaps, std::size_t part_count) {
  std::stable_sort(gaps.begin(), gaps.end(), [](const OffsetGap& a, const OffsetGap& b) {
    return a.clearance_m > b.clearance_m;
  });
  PartGroups groups(part_count);
  std::vector<OffsetGap> kept;
  for (OffsetGap& gap : gaps) {
    if (groups.find(gap.from_part) == groups.find(gap.to_part)) continue;
    groups.join(gap.from_part, gap.to_part);
    kept.push_back(std::move(gap));
  }
  return kept;
}

/// True when the gaps join all parts into one group.
bool joinsAll(const std::vector<OffsetGap>& gaps, std::size_t part_count) {
  PartGroups groups(part_count);
  for (const OffsetGap& gap : gaps) groups.join(gap.from_part, gap.to_part);
  for (std::size_t k = 1; k < part_count; ++k) {
    if (groups.find(k) != groups.find(0)) return false;
  }
  return true;
}

/// Rounding of the Boolean operations at the free area's scale.
double vertexTolerance(const PolygonWithHoles& free_area) {
  double scale = 1.0;
  for (const Point2& p : free_area.hull) scale = std::max(scale, p.cwiseAbs().maxCoeff());
  return kRelativeVertexTolerance * scale;
}

/// The half-width of a gap's corridor: a transit in it keeps the gap clearance within
/// kClearanceTolerance (a gap of exactly the wall distance gets a corridor about a
/// millimetre wide), and at most kCorridorShare of the gap's clearance.
double corridorHalfWidth(const OffsetGap& gap, double gap_clearance) {
  const double room =
      std::max(gap.clearance_m - gap_clearance + kClearanceTolerance, 0.5 * kClearanceTolerance);
  return std::min(kCorridorShare * gap.clearance_m, room / std::sqrt(2.0));
}

/// The anchor's group, its parts and the corridors of its gaps (moved to `route_gaps`)
/// united into one area: the component that holds the anchor part (`tolerance`: rounding).
PolygonWithHoles routeArea(const std::vector<PolygonWithHoles>& parts, std::size_t anchor,
                           PartGroups& groups, std::vector<OffsetGap>& gaps, double gap_clearance,
                           double tolerance, std::vector<OffsetGap>* route_gaps) {
  std::vector<PolygonWithHoles> pieces;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    if (groups.find(k) == groups.find(anchor)) pieces.push_back(parts[k]);
  }
  for (OffsetGap& gap : gaps) {
    if (groups.find(gap.from_part) != groups.find(anchor)) continue;
    const std::vector<PolygonWithHoles> strips =
        corridor(gap.path, corridorHalfWidth(gap, gap_clearance));
    pieces.insert(pieces.end(), strips.begin(), strips.end());
    route_gaps->push_back(std::move(gap));
  }
  // A part's first vertex lies on the united boundary or inside it, up to rounding.
  for (const PolygonWithHoles& component : unionOfAreas(pieces)) {
    if (contains(component, parts[anchor].hull.front(), tolerance)) {
      return component;
    }
  }
  return {};
}

/// For every part outside the anchor's group: the narrow gap (widest first) that first
/// joins its group to the anchor's, the bottleneck of its widest passage.
std::vector<std::optional<OffsetGap>> widestPassages(const std::vector<OffsetGap>& narrow,
                                                     std::size_t anchor, PartGroups reach,
                                                     std::size_t part_count) {
  std::vector<std::optional<OffsetGap>> widest(part_count);
  for (const OffsetGap& gap : narrow) {
    const std::size_t a = reach.find(gap.from_part);
    const std::size_t b = reach.find(gap.to_part);
    const std::size_t anchor_group = reach.find(anchor);
    if (a != b && (a == anchor_group || b == anchor_group)) {
      const std::size_t other = a == anchor_group ? b : a;
      for (std::size_t k = 0; k < part_count; ++k) {
        if (reach.find(k) == other) widest[k] = gap;
      }
    }
    reach.join(gap.from_part, gap.to_part);
  }
  return widest;
}

}  // namespace

OffsetPartJoiner::OffsetPartJoiner(const PolygonWithHoles& free_area, double wall_distance,
                                   double gap_clearance)
    : free_area_(free_area), wall_distance_(wall_distance), gap_clearance_(gap_clearance) {}

JoinedOffsetArea OffsetPartJoiner::join(const std::vector<PolygonWithHoles>& parts,
                                        std::size_t anchor) const {
  JoinedOffsetArea result;
  if (parts.size() <= 1) {
    if (!parts.empty()) result.route_area = parts.front();
    for (std::size_t k = 0; k < parts.size(); ++k) result.joined_parts.push_back(k);
    return result;
  }
  const SearchLevels levels = searchLevels(wall_distance_, gap_clearance_);
  std::vector<OffsetGap> gaps;
  if (vertexCount(free_area_) > kWindowedJoinVertices) {
    gaps = widestFirst(windowedGaps(free_area_, parts, wall_distance_, levels), parts.size());
  }
  if (!joinsAll(gaps, parts.size())) {
    std::vector<PartVertices> all;
    std::vector<std::size_t> owner;
    for (std::size_t k = 0; k < parts.size(); ++k) {
      all.push_back(verticesOf(parts[k]));
      owner.push_back(k);
    }
    gaps = widestFirst(
        gapsIn(free_area_, all, owner, parts.size(), wall_distance_, levels, free_area_),
        parts.size());
  }
  // The gaps that keep the gap clearance join the parts; the narrower ones name the
  // widest passage to each part left apart.
  PartGroups groups(parts.size());
  std::vector<OffsetGap> passed;
  std::vector<OffsetGap> narrow;
  for (OffsetGap& gap : gaps) {
    if (keepsClearance(gap.clearance_m, gap_clearance_)) {
      groups.join(gap.from_part, gap.to_part);
      passed.push_back(std::move(gap));
    } else {
      narrow.push_back(std::move(gap));
    }
  }
  const double tolerance = vertexTolerance(free_area_);
  result.route_area =
      routeArea(parts, anchor, groups, passed, gap_clearance_, tolerance, &result.gaps);
  std::vector<std::optional<OffsetGap>> widest =
      widestPassages(narrow, anchor, groups, parts.size());
  for (std::size_t k = 0; k < parts.size(); ++k) {
    if (groups.find(k) == groups.find(anchor) &&
        contains(result.route_area, parts[k].hull.front(), tolerance)) {
      result.joined_parts.push_back(k);
    } else {
      result.sealed_parts.push_back({k, std::move(widest[k])});
    }
  }
  return result;
}

}  // namespace kinematic_coverage::core
