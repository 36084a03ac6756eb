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

/// Gaps whose clearance is below this share of the wall distance are sealed: no robot
/// passes a pinch point, and offsets at smaller distances add nothing but cost.
constexpr double kMinClearanceShare = 0.02;
/// A bracket of offset distances in which the parts' grouping changes is halved this many
/// times: the gap's clearance is found to (1 - kMinClearanceShare) / 32, about 3 % of the
/// wall distance, with about 5 offsets per gap.
constexpr int kRefinementDepth = 5;
/// Half-width of a transit corridor, as a share of its path's clearance: the corridor
/// stays inside the free area, and a transit in it keeps 86 % of the path's clearance
/// (the corridor's corners lie at sqrt(2) half-widths from the path).
constexpr double kCorridorShare = 0.1;
/// Rounding of the Boolean operations' results, relative to the map's scale.
constexpr double kRelativeVertexTolerance = 1e-9;

/// The offset free area at one distance and the component each part falls into.
struct Level {
  double distance = 0.0;
  std::vector<PolygonWithHoles> components;
  std::vector<int> component_of_part;  ///< -1: the part lies in no component
};

Level levelAt(const PolygonWithHoles& free_area, const std::vector<PolygonWithHoles>& parts,
              double distance) {
  Level level;
  level.distance = distance;
  level.components = computeOffsetFreeArea(free_area, distance).parts;
  for (const PolygonWithHoles& part : parts) {
    // A part lies deep inside the offset at a smaller distance (offsets are nested), so
    // one of its vertices tells which component holds it.
    int found = -1;
    for (std::size_t c = 0; c < level.components.size() && found < 0; ++c) {
      if (contains(level.components[c], part.hull.front())) found = static_cast<int>(c);
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
void refine(const PolygonWithHoles& free_area, const std::vector<PolygonWithHoles>& parts,
            const Level& lower, const Level& upper, int depth, std::vector<Merge>* merges) {
  const std::vector<int> lower_groups = grouping(lower);
  const std::vector<int> upper_groups = grouping(upper);
  if (lower_groups == upper_groups) return;
  if (depth == 0) {
    merges->push_back({lower, upper_groups});
    return;
  }
  const Level middle = levelAt(free_area, parts, 0.5 * (lower.distance + upper.distance));
  refine(free_area, parts, middle, upper, depth - 1, merges);
  refine(free_area, parts, lower, middle, depth - 1, merges);
}

/// The closest pair of boundary vertices, one of the parts in `from`, one of those in `to`.
std::pair<Point2, Point2> closestVertices(const std::vector<PolygonWithHoles>& parts,
                                          const std::vector<std::size_t>& from,
                                          const std::vector<std::size_t>& to,
                                          std::size_t* from_part, std::size_t* to_part) {
  auto vertices = [&](std::size_t k) {
    std::vector<Point2> result = parts[k].hull;
    for (const Ring& hole : parts[k].holes) result.insert(result.end(), hole.begin(), hole.end());
    return result;
  };
  std::vector<std::vector<Point2>> to_vertices;
  for (std::size_t j : to) to_vertices.push_back(vertices(j));
  double best = std::numeric_limits<double>::infinity();
  std::pair<Point2, Point2> result;
  for (std::size_t i : from) {
    const std::vector<Point2> a = vertices(i);
    for (std::size_t k = 0; k < to.size(); ++k) {
      const std::size_t j = to[k];
      for (const Point2& q : to_vertices[k]) {
        for (const Point2& p : a) {
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
  double least = std::numeric_limits<double>::infinity();
  Point2 where = path.front();
  auto visit = [&](const Ring& ring) {
    for (std::size_t e = 0, n = ring.size(); e < n; ++e) {
      const Point2& c = ring[e];
      const Point2& d = ring[(e + 1) % n];
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

}  // namespace

OffsetPartJoiner::OffsetPartJoiner(const PolygonWithHoles& free_area, double wall_distance)
    : free_area_(free_area), wall_distance_(wall_distance) {}

JoinedOffsetArea OffsetPartJoiner::join(const std::vector<PolygonWithHoles>& parts,
                                        std::size_t anchor) const {
  JoinedOffsetArea result;
  if (parts.size() <= 1) {
    if (!parts.empty()) result.route_area = parts.front();
    for (std::size_t k = 0; k < parts.size(); ++k) result.joined_parts.push_back(k);
    return result;
  }
  Level upper;
  upper.distance = wall_distance_;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    upper.component_of_part.push_back(static_cast<int>(k));
  }
  const Level lower = levelAt(free_area_, parts, kMinClearanceShare * wall_distance_);
  std::vector<Merge> merges;
  refine(free_area_, parts, lower, upper, kRefinementDepth, &merges);

  // Groups already joined, as a union-find over the parts.
  std::vector<std::size_t> root(parts.size());
  for (std::size_t k = 0; k < parts.size(); ++k) root[k] = k;
  auto find = [&](std::size_t k) {
    while (root[k] != k) k = root[k] = root[root[k]];
    return k;
  };
  const SegmentCost distance_cost(CostFunction::kDistance, VehicleLimits{});
  std::vector<OffsetGap> gaps;
  for (const Merge& merge : merges) {
    for (std::size_t c = 0; c < merge.lower.components.size(); ++c) {
      // The groups (at the merge's upper distance) that this component holds.
      std::map<std::size_t, std::vector<std::size_t>> groups;
      for (std::size_t k = 0; k < parts.size(); ++k) {
        if (merge.lower.component_of_part[k] == static_cast<int>(c)) groups[find(k)].push_back(k);
      }
      if (groups.size() <= 1) continue;
      const VisibilityGraph graph(merge.lower.components[c], distance_cost);
      std::vector<std::size_t> joined = groups.begin()->second;
      for (auto it = std::next(groups.begin()); it != groups.end(); ++it) {
        OffsetGap gap;
        const auto [a, b] =
            closestVertices(parts, joined, it->second, &gap.from_part, &gap.to_part);
        gap.path = graph.shortestPath(a, b);
        std::tie(gap.clearance_m, gap.narrowest_point) = pathClearance(free_area_, gap.path);
        root[find(gap.to_part)] = find(gap.from_part);
        joined.insert(joined.end(), it->second.begin(), it->second.end());
        gaps.push_back(std::move(gap));
      }
    }
  }

  // The anchor's group, its parts and corridors united into one area.
  std::vector<PolygonWithHoles> pieces;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    if (find(k) == find(anchor)) pieces.push_back(parts[k]);
  }
  for (OffsetGap& gap : gaps) {
    if (find(gap.from_part) != find(anchor)) continue;
    const std::vector<PolygonWithHoles> strips =
        corridor(gap.path, kCorridorShare * gap.clearance_m);
    pieces.insert(pieces.end(), strips.begin(), strips.end());
    result.gaps.push_back(std::move(gap));
  }
  // A part's first vertex lies on the united boundary or inside it, up to rounding.
  double scale = 1.0;
  for (const Point2& p : free_area_.hull) scale = std::max(scale, p.cwiseAbs().maxCoeff());
  const double tolerance = kRelativeVertexTolerance * scale;
  for (const PolygonWithHoles& component : unionOfAreas(pieces)) {
    if (contains(component, parts[anchor].hull.front(), tolerance)) {
      result.route_area = component;
      break;
    }
  }
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const bool joined =
        find(k) == find(anchor) && contains(result.route_area, parts[k].hull.front(), tolerance);
    (joined ? result.joined_parts : result.sealed_parts).push_back(k);
  }
  return result;
}

}  // namespace kinematic_coverage::core
