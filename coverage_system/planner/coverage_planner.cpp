#include "coverage_system/planner/coverage_planner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <future>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <utility>

#include "coverage_system/parameters/parameter_choices.h"
#include "coverage_system/parameters/stage_options.h"
#include "coverage_system/planner/lazy_transition_costs.h"
#include "coverage_system/planner/reachable_offset_parts.h"
#include "polygon_coverage_ros_bridge/base/elapsed_seconds.h"
#include "polygon_coverage_ros_bridge/base/parallel_for.h"
#include "polygon_coverage_ros_bridge/decomposition/best_decomposition.h"
#include "polygon_coverage_ros_bridge/geometry/boundary_simplification.h"
#include "polygon_coverage_ros_bridge/geometry/internal_error.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/geometry/region_intersection.h"
#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"
#include "polygon_coverage_ros_bridge/gtsp/gtsp_instance.h"
#include "polygon_coverage_ros_bridge/repair/unseen_area_repair.h"
#include "polygon_coverage_ros_bridge/route/jog_removal.h"
#include "polygon_coverage_ros_bridge/route/segment_cost.h"
#include "polygon_coverage_ros_bridge/route/visibility_graph.h"
#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"
#include "polygon_coverage_ros_bridge/sweeps/sweep_pattern.h"

namespace kinematic_coverage::core {
namespace {

using Clock = std::chrono::steady_clock;

/// Waypoints closer than this are one waypoint (metres; and relative to the map's scale
/// for very large maps): the same vertex computed two ways differs by rounding only.
constexpr double kDuplicateWaypointTolerance = 5e-7;
constexpr double kRelativeDuplicateTolerance = 1e-9;
/// A point this close (relative) to the offset free area counts as inside it.
constexpr double kRelativeInsideTolerance = 1e-9;
/// Clusters up to which the GTSP is solved exactly (the subset dynamic programme).
constexpr int kExactClusterLimit = 14;
/// The planner's effort rule for the memetic GTSP solver, whose defaults are tuned on
/// GTSPLIB (a population of up to 100, stall windows of clamp(20 + clusters / 3, 30, 80)
/// generations): a population of at most 30 (10 + clusters / 2 below 40 clusters), with
/// the focused search (GtspOptions) above 50 clusters.
constexpr int kGtspMaxPopulation = 30;
/// Stall window: clamp(5 + clusters / 3, 15, 80) generations. The search stops when the
/// best tour did not improve over a window, or improved by less than kGtspMinStallGain.
/// Against 50 and clamp(20 + clusters / 3, 30, 80), on the 80 maps of planner_reference
/// (`planner_reference --runs 1` at both settings): 27 tours changed, from 0.25 % cheaper
/// to 0.68 % costlier, mean cost +0.05 %; planning time (geometric mean of the ratios to the
/// recorded times) 0.31 -> 0.20.
constexpr int kGtspStallBase = 5;
constexpr int kGtspMinStallGenerations = 15;
constexpr int kGtspMaxStallGenerations = 80;
/// Clusters above which the population and the stall window shrink in proportion to
/// kGtspLargeClusters / clusters, to at least kGtspMinLargePopulation and
/// kGtspMinStallGenerations: on an archipelago of 2 096 cells, 30 tours over windows of 80
/// generations of about a second each ran into the 60 s safety cap; 10 tours over 22
/// generations stop by the rule in about 14 s, 0.3 % above a run with ten times the window
/// (docs/BENCHMARKS.md, Lake charts). From 300 rather than 600 clusters: on three rough
/// shores of 2 000 vertices (414 to 427 cells) and three lake charts of 10 000 (427 to 513),
/// the tours found their best within about ten generations and then stalled for 80; the
/// solve took 30 to 70 % less time for tours 0.01 to 0.06 % costlier, all within 0.13 % of
/// ten times the window (at 200 clusters, up to 0.34 %).
constexpr int kGtspLargeClusters = 300;
constexpr int kGtspMinLargePopulation = 10;
/// The memetic GTSP solver stops when its last stall generations made the best tour less
/// than this share cheaper: on shoreline maps of 230 to 370 trapezoidal cells, half the
/// solving time (17.7 -> 8.4 s, 4.9 -> 2.5 s) for tours at most 0.08 % costlier; where
/// gains stop sooner, as before.
constexpr double kGtspMinStallGain = 1e-3;
/// With cell_joining longest_overlap, a map whose Choset decomposition has at most this many
/// cells is planned with those cells too, and the cheaper tour kept: on small maps the
/// extra cells can let the tour turn back sooner (a 30 m lake with two islands: 7 % cheaper
/// than with the joined cells), and solving both costs little there.
constexpr std::size_t kChosetAlternativeCellLimit = 50;
static_assert(PlanningOptions().dense_route_corners == VisibilityGraph::kOnDemandNodes,
              "the planner's default switches the visibility graph where the graph would");
/// Parts of a coverage region smaller than this share of a square sweep distance are
/// left out: rounding leftovers of the Boolean operations, not area to sweep.
constexpr double kMinPartShare = 1e-4;

std::string formatPoint(const Point2& p) {
  std::ostringstream out;
  out << "(" << p.x() << ", " << p.y() << ")";
  return out.str();
}

/// Parameters in [0, 1] that cut the segment [a, b] where it crosses the ring's edges,
/// sorted, with both ends.
std::vector<double> ringCrossings(const Ring& ring, const Point2& a, const Point2& b) {
  std::vector<double> ts = {0.0, 1.0};
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const Point2& c = ring[i];
    const Point2& d = ring[(i + 1) % n];
    const double denominator = cross({0, 0}, b - a, d - c);
    if (denominator == 0.0) continue;
    const double t = cross({0, 0}, c - a, d - c) / denominator;
    const double u = cross({0, 0}, c - a, b - a) / denominator;
    if (t > 0.0 && t < 1.0 && u >= 0.0 && u <= 1.0) ts.push_back(t);
  }
  std::sort(ts.begin(), ts.end());
  return ts;
}

/// True when the segment [a, b] passes through the interior of a hole (more than
/// `tolerance` inside it): the segment is cut where it crosses the hole's edges and the
/// middle of every piece is tested.
bool crossesHole(const std::vector<Ring>& holes, const Point2& a, const Point2& b,
                 double tolerance) {
  for (const Ring& hole : holes) {
    const std::vector<double> ts = ringCrossings(hole, a, b);
    for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
      const Point2 mid = a + 0.5 * (ts[i] + ts[i + 1]) * (b - a);
      if (insideRing(mid, hole) && distanceToRing(mid, hole) > tolerance) return true;
    }
  }
  return false;
}

/// True when the segment from a (inside the hull or outside it, as a robot launched from a
/// boat) to b (inside) leaves the hull after it has entered it: through a wall between two
/// bays, say.
bool leavesTheHull(const Ring& hull, const Point2& a, const Point2& b, double tolerance) {
  const std::vector<double> ts = ringCrossings(hull, a, b);
  bool entered = false;
  for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
    const Point2 mid = a + 0.5 * (ts[i] + ts[i + 1]) * (b - a);
    const bool outside = !insideRing(mid, hull) && distanceToRing(mid, hull) > tolerance;
    if (outside && entered) return true;
    if (!outside) entered = true;
  }
  return false;
}

/// Where a start or goal enters the planned area: itself when inside the route area,
/// otherwise the nearest point of the planned parts, joined by a straight leg. A leg that
/// crosses a hole is invalid input (docs/REFERENCE.md, Geometry and input rules); where
/// the leg to the nearest point would leave the hull (a goal in a bay narrower than two
/// wall distances, its nearest point across the wall in the next bay), the nearest point
/// whose leg stays in the free area is taken, and without one the request is invalid.
Point2 entryPoint(const PolygonWithHoles& free_area, const PolygonWithHoles& route_area,
                  const std::vector<PolygonWithHoles>& parts, const Point2& p,
                  const std::string& what, double tolerance) {
  if (!std::isfinite(p.x()) || !std::isfinite(p.y())) {
    throw InvalidInputError(what + " has a non-finite coordinate");
  }
  for (std::size_t i = 0; i < free_area.holes.size(); ++i) {
    if (insideRing(p, free_area.holes[i]) && distanceToRing(p, free_area.holes[i]) > tolerance) {
      throw InvalidInputError(what + " " + formatPoint(p) + " lies inside hole " +
                              std::to_string(i));
    }
  }
  if (contains(route_area, p, tolerance)) return p;
  // The nearest point of every boundary edge of the parts, nearest first.
  std::vector<std::pair<double, Point2>> candidates;
  auto visit = [&](const Ring& ring) {
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      const Point2 q = closestPointOnSegment(p, ring[i], ring[(i + 1) % n]);
      candidates.emplace_back((q - p).norm(), q);
    }
  };
  for (const PolygonWithHoles& part : parts) {
    visit(part.hull);
    for (const Ring& hole : part.holes) visit(hole);
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  const Point2 nearest = candidates.front().second;
  if (crossesHole(free_area.holes, p, nearest, tolerance)) {
    throw InvalidInputError(what + " " + formatPoint(p) +
                            " is outside the offset free area and its straight leg to the "
                            "nearest point " +
                            formatPoint(nearest) + " crosses a hole");
  }
  for (const auto& [distance, entry] : candidates) {
    if (!leavesTheHull(free_area.hull, p, entry, tolerance) &&
        !crossesHole(free_area.holes, p, entry, tolerance)) {
      return entry;
    }
  }
  throw InvalidInputError(what + " " + formatPoint(p) +
                          " is outside the offset free area and no straight leg inside the "
                          "free area joins it to the offset free area (its nearest point " +
                          formatPoint(nearest) + " lies across the hull)");
}

std::string partName(const PolygonWithHoles& part) {
  std::ostringstream name;
  name << "a part of " << kinematic_coverage::core::area(part) << " m^2 near "
       << formatPoint(part.hull.front());
  return name.str();
}

/// Why a sealed part is not entered: its widest passage, or none.
std::string passageText(const SealedPart& sealed, double gap_clearance) {
  std::ostringstream text;
  if (sealed.widest_passage) {
    text << "the widest gap to it, at " << formatPoint(sealed.widest_passage->narrowest_point)
         << ", has " << sealed.widest_passage->clearance_m << " m clearance, below gap_clearance "
         << gap_clearance << " m";
  } else {
    text << "no gap to it is wider than a pinch point";
  }
  return text.str();
}

/// The parts to plan and the area their transitions run in, by `offset_parts`, with a
/// warning per gap passed narrower than the wall distance and per part left out. With
/// `all`, the parts beyond gaps narrower than gap_clearance move from plan->offset_parts to
/// plan->unreachable_parts, each with its passageText in `passages`; a goal inside one is
/// refused.
std::vector<PolygonWithHoles> partsToPlan(const PolygonWithHoles& free_area,
                                          const PlanningOptions& options, const Point2& start,
                                          const Point2& goal, double tolerance, CoveragePlan* plan,
                                          std::vector<std::string>* passages) {
  const std::vector<PolygonWithHoles> parts = plan->offset_parts;
  if (parts.size() == 1) {
    plan->route_area = parts.front();
    return parts;
  }
  if (options.offset_parts == OffsetParts::kLargest) {
    for (std::size_t k = 1; k < parts.size(); ++k) {
      plan->warnings.push_back("the wall offset splits the free area: " + partName(parts[k]) +
                               " is not planned (offset_parts: largest)");
    }
    plan->route_area = parts.front();
    return {parts.front()};
  }
  const double gap_clearance = options.gap_clearance;
  JoinedOffsetArea joined = joinOffsetParts(free_area, options, parts, start);
  for (const SealedPart& sealed : joined.sealed_parts) {
    const PolygonWithHoles& part = parts[sealed.part];
    const std::string passage = passageText(sealed, gap_clearance);
    if (contains(part, goal, tolerance)) {
      throw UnreachableGoalError("goal " + formatPoint(goal) + " lies in " + partName(part) +
                                 " of the offset free area that the robot cannot reach from the "
                                 "start: " +
                                 passage);
    }
    plan->warnings.push_back("the wall offset splits the free area: " + partName(part) +
                             " is not entered (it counts as unreachable): " + passage);
    plan->unreachable_parts.push_back(part);
    passages->push_back(passage);
  }
  // Only the parts joined stay in the offset free area; the gaps name them by new index.
  std::vector<std::size_t> index_of(parts.size(), 0);
  plan->offset_parts.clear();
  for (std::size_t k : joined.joined_parts) {
    index_of[k] = plan->offset_parts.size();
    plan->offset_parts.push_back(parts[k]);
  }
  for (OffsetGap& gap : joined.gaps) {
    if (!keepsClearance(gap.clearance_m, options.wall_distance)) {
      std::ostringstream warning;
      warning << "the wall offset splits the free area: transits to "
              << partName(parts[gap.to_part]) << " pass a gap at "
              << formatPoint(gap.narrowest_point) << " with " << gap.clearance_m
              << " m clearance, nearer than wall_distance " << options.wall_distance
              << " m (gap_clearance " << gap_clearance << " m allows it)";
      plan->warnings.push_back(warning.str());
    }
    gap.from_part = index_of[gap.from_part];
    gap.to_part = index_of[gap.to_part];
  }
  plan->route_area = std::move(joined.route_area);
  plan->gaps = std::move(joined.gaps);
  return plan->offset_parts;
}

/// Start and goal: the generalized TSP's nodes 0 and 1, before the sweep patterns.
constexpr std::size_t kTerminalNodes = 2;

/// For every pattern, the pattern of the same cell and direction that runs its path the
/// other way (start and end swapped), or itself: GtspInstance::reverse_nodes (node k + 2
/// for pattern k; start and goal are their own reverses).
std::vector<int> reverseNodes(const std::vector<SweepPattern>& patterns,
                              const std::vector<std::vector<int>>& clusters) {
  std::vector<int> reverse(patterns.size() + kTerminalNodes);
  for (std::size_t node = 0; node < reverse.size(); ++node) reverse[node] = static_cast<int>(node);
  for (const std::vector<int>& cluster : clusters) {
    for (int node : cluster) {
      if (node < static_cast<int>(kTerminalNodes)) continue;
      const SweepPattern& pattern = patterns[static_cast<std::size_t>(node) - kTerminalNodes];
      for (int other : cluster) {
        const SweepPattern& candidate = patterns[static_cast<std::size_t>(other) - kTerminalNodes];
        if (candidate.direction == pattern.direction && candidate.start() == pattern.end() &&
            candidate.end() == pattern.start()) {
          reverse[static_cast<std::size_t>(node)] = other;
          break;
        }
      }
    }
  }
  return reverse;
}

/// Drops repeated waypoints and waypoints where the path goes straight on, except the
/// protected ones (entry and exit of the offset free area). The first and last points (the
/// start and the goal) stay exactly where they are.
std::vector<Point2> simplifiedPath(const std::vector<Point2>& path, const std::vector<bool>& keep,
                                   double tolerance) {
  std::vector<Point2> points;
  std::vector<bool> kept;
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (!points.empty() && (path[i] - points.back()).norm() <= tolerance) {
      if (keep[i]) kept.back() = true;
      const bool goal = i + 1 == path.size();
      if (goal && points.size() > 1) {
        points.back() = path[i];
      } else if (goal && path[i] != points.back()) {
        points.push_back(path[i]);
        kept.push_back(true);
      }
      continue;
    }
    points.push_back(path[i]);
    kept.push_back(keep[i]);
  }
  std::vector<Point2> result;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!result.empty() && i + 1 < points.size() && !kept[i]) {
      const Point2 in = points[i] - result.back();
      const Point2 out = points[i + 1] - points[i];
      const bool straight_on =
          std::abs(cross({0, 0}, in, out)) <= tolerance * in.norm() && in.dot(out) > 0.0;
      if (straight_on) continue;
    }
    result.push_back(points[i]);
  }
  return result;
}

/// What the stages of one planning run share: the request, the plan being built and the
/// listener that hears of each stage as it finishes.
struct PlanningRun {
  const PlanningOptions& options;
  const PolygonWithHoles& free_area;
  const Point2& start;
  const Point2& goal;
  const StageCallback& on_stage;
  CoveragePlan& plan;
  double tolerance = 0.0;  ///< a point this close to the offset free area is inside it

  /// Records the stage `name` begun at `since`, and tells the listener.
  void stage(const std::string& name, Clock::time_point since, std::string summary) const {
    plan.stages.push_back({name, secondsSince(since), std::move(summary)});
    if (on_stage) on_stage(plan.stages.back());
  }
};

/// The wall offset's result: the parts of the offset free area to plan and where the
/// start and goal enter it.
struct OffsetStage {
  std::vector<PolygonWithHoles> planned_parts;
  Point2 start_inside = Point2::Zero();
  Point2 goal_inside = Point2::Zero();
};

/// Wall offset (docs/REFERENCE.md, Geometry and input rules): the offset free area, its
/// parts to plan joined into the route area, and the start's and goal's entry points.
OffsetStage offsetStage(const PlanningRun& run) {
  const Clock::time_point t = Clock::now();
  CoveragePlan& plan = run.plan;
  plan.offset_parts = computeOffsetFreeArea(run.free_area, run.options.wall_distance,
                                            run.options.offset_miter_limit)
                          .parts;
  const std::size_t part_count = plan.offset_parts.size();
  OffsetStage offset;
  std::vector<std::string> passages;  // one per plan.unreachable_parts
  offset.planned_parts =
      partsToPlan(run.free_area, run.options, run.start, run.goal, run.tolerance, &plan, &passages);
  offset.start_inside = entryPoint(run.free_area, plan.route_area, offset.planned_parts, run.start,
                                   "start", run.tolerance);
  try {
    offset.goal_inside = entryPoint(run.free_area, plan.route_area, offset.planned_parts, run.goal,
                                    "goal", run.tolerance);
  } catch (const InvalidInputError& error) {
    // A goal in the wall band nearer a part the robot cannot reach than the planned ones:
    // say so.
    const std::vector<PolygonWithHoles>& unreachable = plan.unreachable_parts;
    if (unreachable.empty()) throw;
    const std::size_t nearest = nearestPart(unreachable, run.goal);
    const double nearest_distance = distanceToBoundary(run.goal, unreachable[nearest]);
    for (const PolygonWithHoles& part : offset.planned_parts) {
      if (distanceToBoundary(run.goal, part) <= nearest_distance) throw;
    }
    throw UnreachableGoalError(std::string(error.what()) +
                               "; the part of the offset free area nearest it, " +
                               partName(unreachable[nearest]) +
                               ", cannot be reached from the start: " + passages[nearest]);
  }
  std::size_t holes = 0;
  for (const PolygonWithHoles& part : plan.offset_parts) holes += part.holes.size();
  std::ostringstream summary;
  summary << "offset free area " << area(plan.offset_parts) << " m^2 with " << holes << " holes";
  if (part_count > 1) {
    summary << " in " << part_count << " parts, " << offset.planned_parts.size()
            << " planned, joined through " << plan.gaps.size() << " gaps";
  }
  run.stage("offset", t, summary.str());
  return offset;
}

/// The parts of the planned parts inside the coverage region (replanning).
std::vector<PolygonWithHoles> regionStage(const PlanningRun& run,
                                          const std::vector<PolygonWithHoles>& planned_parts,
                                          const std::vector<PolygonWithHoles>& coverage_region) {
  const Clock::time_point t = Clock::now();
  const FrustumSensor region_sensor = run.options.frustumSensor();
  std::vector<PolygonWithHoles> parts;
  for (const PolygonWithHoles& part : planned_parts) {
    for (PolygonWithHoles& inside : intersectWithRegions(
             part, coverage_region,
             kMinPartShare * region_sensor.sweepDistance() * region_sensor.sweepDistance())) {
      parts.push_back(std::move(inside));
    }
  }
  double parts_area = 0.0;
  for (const PolygonWithHoles& part : parts) parts_area += area(part);
  std::ostringstream summary;
  summary << parts.size() << " parts of the offset free area to cover, " << parts_area << " m^2";
  run.stage("region", t, summary.str());
  return parts;
}

/// The parts to decompose: the parts to cover with their boundaries simplified inward
/// within boundary_simplification sweep distances (BoundarySimplification), or the parts
/// themselves when that is 0 (no stage recorded then).
std::vector<PolygonWithHoles> simplifyStage(const PlanningRun& run,
                                            const std::vector<PolygonWithHoles>& parts,
                                            double tolerance) {
  if (tolerance <= 0.0) return parts;
  const Clock::time_point t = Clock::now();
  const BoundarySimplification simplification(tolerance);
  std::vector<PolygonWithHoles> simplified;
  std::size_t before = 0;
  std::size_t after = 0;
  for (const PolygonWithHoles& part : parts) {
    simplified.push_back(simplification.simplify(part));
    before += BoundarySimplification::vertexCount(part);
    after += BoundarySimplification::vertexCount(simplified.back());
  }
  std::ostringstream summary;
  summary << "boundary simplified inward within " << tolerance << " m: " << before << " -> "
          << after << " vertices";
  run.stage("simplify", t, summary.str());
  return simplified;
}

/// Cell decomposition over candidate directions, per part, within the size limits.
std::vector<Decomposition> decomposeStage(const PlanningRun& run,
                                          const std::vector<PolygonWithHoles>& parts,
                                          CellJoining joining) {
  const Clock::time_point t = Clock::now();
  const DecompositionType type = run.options.decomposition_type;
  DecompositionOptions options;
  options.joining = joining;
  std::vector<Decomposition> decompositions;
  std::size_t directions_tried = 0;
  std::size_t cell_count = 0;
  for (const PolygonWithHoles& part : parts) {
    decompositions.push_back(computeBestDecomposition(part, type, options));
    directions_tried = std::max(directions_tried, decompositions.back().directions_tried);
    cell_count += decompositions.back().cells.size();
    for (const Cell& cell : decompositions.back().cells) run.plan.cells.push_back(cell.polygon);
  }
  std::ostringstream summary;
  summary << cell_count << " " << nameOf(type, kDecompositionTypes) << " cells"
          << (joining == CellJoining::kLongestOverlap ? " (joined across critical points)" : "")
          << ", best of " << directions_tried << " directions";

  // Size limits, before anything of their size is built.
  if (const std::size_t dropped = fitDirectionsToGtspLimit(decompositions); dropped > 0) {
    run.plan.warnings.push_back(
        "kept only the best lane directions of the cells: " + std::to_string(dropped) +
        " of their other directions would have taken the generalized TSP over " +
        std::to_string(kMaxGtspNodes) + " nodes");
  }
  PlanSize size{cell_count, gtspNodeCount(decompositions), routeCorners(run.plan.route_area)};
  size.routes_on_demand = size.route_corners > run.options.dense_route_corners;
  size.lazy_transitions = size.gtsp_nodes > run.options.dense_transition_nodes;
  const double max_memory_mb =
      run.options.max_memory_mb > 0.0 ? run.options.max_memory_mb : machineMaxMemoryMb();
  const double estimate_mb = checkMemoryEstimate(size, max_memory_mb, type);
  checkLaneLimit(decompositions, run.options.sensor);
  summary << "; memory estimate " << std::lround(estimate_mb) << " MB (" << size.gtsp_nodes
          << " generalized TSP nodes, " << size.route_corners << " route corners)";
  run.stage("decompose", t, summary.str());
  return decompositions;
}

/// The sweep patterns of every cell and direction, and the GTSP's clusters: start, goal,
/// then one per cell with the nodes of its patterns.
struct SweepStage {
  std::vector<SweepPattern> patterns;
  std::vector<std::vector<int>> clusters;
};

/// Warns when the footprint is longer than wide: lanes see W/2 beside them, but the
/// reachable area reaches L/2 from the offset free area, so along walls parallel to the
/// lanes what lies between stays unseen.
void warnOfALongFootprint(const FrustumSensor& sensor, CoveragePlan* plan) {
  if (sensor.length() <= sensor.width()) return;
  std::ostringstream warning;
  warning << "the footprint is longer (L " << sensor.length() << " m) than wide (W "
          << sensor.width() << " m): along walls parallel to the lanes a band up to "
          << 0.5 * (sensor.length() - sensor.width())
          << " m wide of the reachable area stays unseen (see unseen_reachable_area_m2)";
  plan->warnings.push_back(warning.str());
}

/// The parts to cover and what was decomposed of them: the same parts, or their
/// simplifications (simplifyStage).
struct DecomposedParts {
  const std::vector<PolygonWithHoles>& exact;
  const std::vector<PolygonWithHoles>& decomposed;
};

/// Sweep patterns per cell and direction, spaced by the sensor's footprint (begun at
/// `since`, which includes building the visibility graph); lanes end at the exact parts'
/// boundaries.
SweepStage sweepStage(const PlanningRun& run, Clock::time_point since, const DecomposedParts& parts,
                      const std::vector<Decomposition>& decompositions, const FrustumSensor& sensor,
                      const VisibilityGraph& graph) {
  warnOfALongFootprint(sensor, &run.plan);
  std::vector<SweepPatternGenerator> generators;
  generators.reserve(parts.exact.size());
  std::vector<std::pair<std::size_t, const Cell*>> cells;  // part, cell
  for (std::size_t k = 0; k < parts.exact.size(); ++k) {
    generators.emplace_back(sensor,
                            SweepPatternGenerator::laneEndInset(sensor, run.options.wall_distance),
                            parts.decomposed[k], parts.exact[k]);
    for (const Cell& cell : decompositions[k].cells) cells.emplace_back(k, &cell);
  }
  // The cells' patterns on every hardware thread, each cell's transitions routed with its
  // own cache of located lane ends.
  std::vector<std::vector<SweepPattern>> cell_patterns(cells.size());
  parallelForInOrder(cells.size(), [&](std::size_t i) {
    VisibilityGraph::PointCache lane_ends;
    const TransitionPath transition = [&](const Point2& a, const Point2& b) {
      return graph.shortestPath(a, b, &lane_ends);
    };
    const auto& [k, cell] = cells[i];
    for (double direction : cell->sweep_directions) {
      for (SweepPattern& pattern : generators[k].patterns(cell->polygon, direction, transition)) {
        cell_patterns[i].push_back(std::move(pattern));
      }
    }
  });
  SweepStage sweeps;
  sweeps.clusters = {{0}, {1}};  // start, goal
  for (std::vector<SweepPattern>& patterns : cell_patterns) {
    std::vector<int> cluster;
    for (SweepPattern& pattern : patterns) {
      cluster.push_back(static_cast<int>(sweeps.patterns.size()) + 2);
      sweeps.patterns.push_back(std::move(pattern));
    }
    sweeps.clusters.push_back(std::move(cluster));
  }
  std::ostringstream summary;
  summary << sweeps.patterns.size() << " sweep patterns, a visibility graph of "
          << graph.nodeCount() << " corners";
  run.stage("sweeps", since, summary.str());
  return sweeps;
}

/// The visibility graph of the route area: searched on demand beyond
/// PlanningOptions::dense_route_corners corners.
VisibilityGraph routeGraph(const PolygonWithHoles& route_area, const SegmentCost& segment_cost,
                           const PlanningOptions& options) {
  return VisibilityGraph(route_area, segment_cost,
                         routeCorners(route_area) > options.dense_route_corners
                             ? VisibilityGraph::AllPairs::kOnDemand
                             : VisibilityGraph::AllPairs::kByDensity);
}

/// The generalized TSP instance and, on large maps, the transitions still to be priced.
struct TransitionCosts {
  GtspInstance instance;
  std::unique_ptr<LazyTransitionCosts> lazy;
};

/// Large maps: exact transition costs between nearby cells only (LazyTransitionCosts).
void lazyTransitions(const SweepStage& sweeps, const OffsetStage& offset,
                     const VisibilityGraph& graph, const SegmentCost& segment_cost,
                     const std::vector<double>& pattern_costs, TransitionCosts* transitions) {
  std::vector<Point2> sources = {offset.start_inside, offset.goal_inside};
  std::vector<Point2> targets = sources;
  std::vector<double> entering = {0.0, 0.0};
  for (std::size_t k = 0; k < sweeps.patterns.size(); ++k) {
    sources.push_back(sweeps.patterns[k].end());
    targets.push_back(sweeps.patterns[k].start());
    entering.push_back(pattern_costs[k]);
  }
  transitions->lazy = std::make_unique<LazyTransitionCosts>(graph, segment_cost, std::move(sources),
                                                            std::move(targets), std::move(entering),
                                                            &transitions->instance);
}

/// The generalized TSP instance: transition costs between every pattern end and every
/// pattern start (shortest paths in the route area), plus the cost of the pattern entered;
/// beyond PlanningOptions::dense_transition_nodes nodes (at 3 534 nodes, a rough shore of
/// 2 000 vertices and 40 islands, the 12.5 million routes took 1.4 s), routed between nearby cells
/// only and estimated elsewhere until a tour uses them.
TransitionCosts transitionStage(const PlanningRun& run, const SweepStage& sweeps,
                                const OffsetStage& offset, const VisibilityGraph& graph,
                                const SegmentCost& segment_cost) {
  const Clock::time_point t = Clock::now();
  const std::size_t n = sweeps.patterns.size() + 2;
  TransitionCosts transitions;
  GtspInstance& instance = transitions.instance;
  instance.node_count = static_cast<int>(n);
  instance.clusters = sweeps.clusters;
  instance.start_cluster = 0;
  instance.goal_cluster = 1;
  instance.reverse_nodes = reverseNodes(sweeps.patterns, sweeps.clusters);
  std::vector<double> pattern_costs;
  for (const SweepPattern& pattern : sweeps.patterns) {
    pattern_costs.push_back(segment_cost.pathCost(pattern.path));
  }
  std::ostringstream summary;
  if (n > run.options.dense_transition_nodes) {
    lazyTransitions(sweeps, offset, graph, segment_cost, pattern_costs, &transitions);
    summary << transitions.lazy->exactCount() << " of " << (n - 1) * (n - 1)
            << " transition costs routed, between nearby cells (the others estimated until a "
               "tour uses them)";
    run.stage("transitions", t, summary.str());
    return transitions;
  }
  std::vector<Point2> sources = {offset.start_inside};
  std::vector<Point2> targets = {offset.goal_inside};
  for (const SweepPattern& pattern : sweeps.patterns) {
    sources.push_back(pattern.end());
    targets.push_back(pattern.start());
  }
  const std::vector<double> transition_costs = graph.costMatrix(sources, targets);
  instance.costs.assign(n * n, 0.0);
  // Node 0 (start) is source row 0; node 1 (goal) is target column 0; pattern k is
  // node k + 2, source row k + 1 and target column k + 1.
  auto sourceRow = [](std::size_t node) { return node == 0 ? 0 : node - 1; };
  parallelFor(n, [&](std::size_t from) {
    if (from == 1) return;  // nothing leaves the goal
    for (std::size_t to = 1; to < n; ++to) {
      if (from == to) continue;
      const std::size_t column = to == 1 ? 0 : to - 1;
      const double entering = to == 1 ? 0.0 : pattern_costs[to - 2];
      instance.costs[from * n + to] =
          transition_costs[sourceRow(from) * targets.size() + column] + entering;
    }
  });
  summary << sources.size() * targets.size() << " transition costs";
  run.stage("transitions", t, summary.str());
  return transitions;
}

/// The warning of a generalized TSP over `cells` cells that its safety cap of `limit_s` ended.
std::string gtspCapWarning(std::size_t cells, double limit_s) {
  std::ostringstream warning;
  warning << "the generalized TSP over " << cells << " cells stopped at its safety cap of "
          << limit_s
          << " s before its own stopping rule: the visiting order is the best found by then "
             "and may cost more than a full search's (a machine this busy or this slow plans a "
             "map this large poorly; the cells are fewer with a larger wall_distance or "
             "boundary_simplification)";
  return warning.str();
}

/// The generalized TSP over the patterns, from start to goal; with lazy transitions, its
/// tour then made exact.
GtspSolution solveStage(const PlanningRun& run, TransitionCosts transitions) {
  const Clock::time_point t = Clock::now();
  GtspInstance& instance = transitions.instance;
  GtspOptions options;
  options.exact_cluster_limit = kExactClusterLimit;
  const int clusters = static_cast<int>(instance.clusters.size());
  options.max_population = kGtspMaxPopulation;
  options.focused_search = true;
  options.min_stall_gain = kGtspMinStallGain;
  int stall_generations =
      std::clamp(kGtspStallBase + clusters / 3, kGtspMinStallGenerations, kGtspMaxStallGenerations);
  if (clusters > kGtspLargeClusters) {
    // A generation's work grows with the clusters: the population and the window shrink
    // in proportion, down to their floors.
    const double share = static_cast<double>(kGtspLargeClusters) / clusters;
    options.population_size =
        std::max(kGtspMinLargePopulation, static_cast<int>(kGtspMaxPopulation * share));
    stall_generations =
        std::max(kGtspMinStallGenerations, static_cast<int>(kGtspMaxStallGenerations * share));
  }
  options.stall_generations =
      static_cast<int>(std::lround(stall_generations * run.options.gtsp_effort));
  options.time_limit_s = run.options.gtsp_time_limit_s;
  GtspSolution solution = solveGtsp(instance, options);
  std::ostringstream summary;
  summary << "visiting order of " << instance.clusters.size() - 2 << " cells, cost ";
  if (transitions.lazy) {
    const std::size_t routed = transitions.lazy->exactCount();
    const Clock::time_point deadline = t + std::chrono::duration_cast<Clock::duration>(
                                               std::chrono::duration<double>(options.time_limit_s));
    solution = transitions.lazy->makeExact(&instance, std::move(solution), deadline);
    summary << solution.cost << " (" << transitions.lazy->exactCount() - routed
            << " estimated transitions routed where tours used them)";
  } else {
    summary << solution.cost;
  }
  if (solution.time_capped) {
    run.plan.gtsp_time_capped = true;
    run.plan.warnings.push_back(gtspCapWarning(instance.clusters.size() - 2, options.time_limit_s));
    summary << ", stopped at the safety cap";
  }
  run.stage("solve", t, summary.str());
  return solution;
}

/// The sweep patterns and the tour through them that the path follows.
struct Tour {
  SweepStage sweeps;
  GtspSolution solution;
};

/// With cells joined across critical points: where Choset's cells are few
/// (kChosetAlternativeCellLimit), plans them too, quietly, and keeps their tour when it is
/// cheaper (their cells and warnings with it). Records the stage `alternative`. Choset's
/// cells are those of the exact parts: a small map whose boundary the simplification
/// changed keeps the plan it had without (lake_3: one vertex dropped, the joined tour 1.6 %
/// costlier than Choset's exact cells).
void chosetAlternativeStage(const PlanningRun& run, const std::vector<PolygonWithHoles>& parts,
                            const OffsetStage& offset, const FrustumSensor& sensor,
                            const VisibilityGraph& graph, const SegmentCost& segment_cost,
                            Tour* tour) {
  const Clock::time_point t = Clock::now();
  const std::size_t joined_cells = tour->sweeps.clusters.size() - kTerminalNodes;
  std::ostringstream summary;
  if (joined_cells > kChosetAlternativeCellLimit) {
    summary << "Choset's cells not planned: the " << joined_cells << " joined cells are more than "
            << kChosetAlternativeCellLimit;
    run.stage("alternative", t, summary.str());
    return;
  }
  CoveragePlan scratch;
  const PlanningRun quiet{run.options,     run.free_area, run.start,    run.goal,
                          StageCallback(), scratch,       run.tolerance};
  const std::vector<Decomposition> decompositions =
      decomposeStage(quiet, parts, CellJoining::kAtCriticalPoints);
  if (scratch.cells.size() > kChosetAlternativeCellLimit) {
    summary << "Choset's cells not planned: " << scratch.cells.size() << " cells, more than "
            << kChosetAlternativeCellLimit;
    run.stage("alternative", t, summary.str());
    return;
  }
  Tour choset;
  choset.sweeps = sweepStage(quiet, t, {parts, parts}, decompositions, sensor, graph);
  choset.solution =
      solveStage(quiet, transitionStage(quiet, choset.sweeps, offset, graph, segment_cost));
  const bool cheaper = choset.solution.cost < tour->solution.cost;
  // Either search cut short may have missed a tour cheaper than the one kept.
  if (scratch.gtsp_time_capped && !run.plan.gtsp_time_capped) {
    run.plan.gtsp_time_capped = true;
    run.plan.warnings.push_back(
        gtspCapWarning(scratch.cells.size(), run.options.gtsp_time_limit_s));
  }
  summary << "Choset's " << scratch.cells.size() << " cells: tour cost " << choset.solution.cost
          << " against " << tour->solution.cost << " with the " << joined_cells
          << " joined cells; kept " << (cheaper ? "Choset's" : "the joined");
  if (cheaper) {
    *tour = std::move(choset);
    run.plan.cells = std::move(scratch.cells);
    for (std::string& warning : scratch.warnings) {
      if (std::find(run.plan.warnings.begin(), run.plan.warnings.end(), warning) ==
          run.plan.warnings.end()) {
        run.plan.warnings.push_back(std::move(warning));
      }
    }
  }
  run.stage("alternative", t, summary.str());
}

/// The waypoint path: the route through the patterns in the solution's order, with
/// which of its points must stay (start, goal, the entry and exit of the offset free
/// area), before and after jog removal and simplification.
struct WaypointRoute {
  std::vector<Point2> path;  ///< the full route, before jog removal
  std::vector<bool> keep;    ///< per point of `path`: must stay
  std::vector<Point2> waypoints;
  double duplicate_tolerance = 0.0;
};

/// Sets the plan's first_inside and last_inside for `waypoints`: the waypoints where the
/// path enters and leaves the offset free area (the start and goal may lie outside it).
void markInsideEnds(const PlanningRun& run, const OffsetStage& offset,
                    const std::vector<Point2>& waypoints) {
  CoveragePlan& plan = run.plan;
  plan.first_inside =
      (waypoints.size() > 1 && (run.start - offset.start_inside).norm() > run.tolerance) ? 1 : 0;
  plan.last_inside = waypoints.size() - 1;
  if (waypoints.size() > 1 && (run.goal - offset.goal_inside).norm() > run.tolerance) {
    plan.last_inside -= 1;
  }
}

/// The route in the solution's order, its jogs removed and its straight or repeated
/// waypoints dropped.
WaypointRoute pathStage(const PlanningRun& run, const OffsetStage& offset, const SweepStage& sweeps,
                        const GtspSolution& solution, const VisibilityGraph& graph,
                        const JogRemoval& jog_removal, double scale) {
  WaypointRoute route;
  route.path = {run.start};
  route.keep = {true};
  auto append = [&](const std::vector<Point2>& points, bool keep_first) {
    for (std::size_t i = 0; i < points.size(); ++i) {
      route.path.push_back(points[i]);
      route.keep.push_back(i == 0 && keep_first);
    }
  };
  append({offset.start_inside}, true);
  // The routes between the patterns (legs[k] leads into the k-th pattern; the last one to
  // the goal), found on every hardware thread.
  std::vector<const SweepPattern*> visited;
  for (int node : solution.nodes) {
    if (node >= 2) visited.push_back(&sweeps.patterns[static_cast<std::size_t>(node - 2)]);
  }
  std::vector<std::vector<Point2>> legs(visited.size() + 1);
  parallelForInOrder(legs.size(), [&](std::size_t k) {
    const Point2& from = k == 0 ? offset.start_inside : visited[k - 1]->end();
    const Point2& to = k < visited.size() ? visited[k]->start() : offset.goal_inside;
    legs[k] = graph.shortestPath(from, to);
  });
  for (std::size_t k = 0; k < visited.size(); ++k) {
    append(legs[k], false);
    append(visited[k]->path, false);
  }
  append(legs.back(), false);
  route.keep.back() = true;
  append({run.goal}, true);
  std::vector<bool> kept;
  const std::vector<Point2> without_jogs = jog_removal.apply(route.path, route.keep, &kept);
  route.duplicate_tolerance =
      std::max(kDuplicateWaypointTolerance, kRelativeDuplicateTolerance * scale);
  route.waypoints = simplifiedPath(without_jogs, kept, route.duplicate_tolerance);
  markInsideEnds(run, offset, route.waypoints);
  return route;
}

/// A stage's summary of a waypoint path: waypoints, length and time cost.
std::string pathSummary(const std::vector<Point2>& waypoints, const SegmentCost& time_cost) {
  std::ostringstream summary;
  summary << waypoints.size() << " waypoints, " << pathLength(waypoints) << " m, time cost "
          << time_cost.pathCost(waypoints) << " s";
  return summary.str();
}

/// The exact offset around the plan's parts, against which coverage is measured, and the
/// repair's raster (UnseenAreaRepair::measuringRaster) on the exact offset around the
/// planned parts (none without coverage_repair), from one round offset.
struct ExactOffsetStage {
  std::vector<PolygonWithHoles> exact_offset_parts;
  std::optional<CoverageEvaluator> measuring_raster;
};

/// ExactOffsetStage, which depends only on the areas: computed on its own thread while the
/// stages from simplify to path run. The arguments must outlive the future.
std::future<ExactOffsetStage> exactOffsetInBackground(
    const PlanningRun& run, const OffsetStage& offset, const FrustumSensor& sensor,
    const std::vector<PolygonWithHoles>* coverage_region) {
  return std::async(std::launch::async, [&run, &offset, &sensor, coverage_region,
                                         offset_parts = run.plan.offset_parts] {
    // With no wall distance the offset is exact: no round parts, and each part stays itself.
    const double wall_distance = run.options.wall_distance;
    const std::vector<PolygonWithHoles> round =
        wall_distance > 0.0
            ? WallOffset(run.free_area).at(wall_distance, OffsetCorners::kRound).parts
            : std::vector<PolygonWithHoles>{};
    ExactOffsetStage stage;
    stage.exact_offset_parts = roundPartsHolding(round, offset_parts);
    if (run.options.coverage_repair) {
      stage.measuring_raster = UnseenAreaRepair::measuringRaster(
          run.free_area, roundPartsHolding(round, offset.planned_parts), sensor, coverage_region);
    }
    return stage;
  });
}

/// Coverage repair: where the sweeps leave reachable area unseen, the jogs removed near it
/// are put back, then patches are driven (UnseenAreaRepair). Returns the summary line.
std::string repairStage(const PlanningRun& run, const OffsetStage& offset,
                        CoverageEvaluator measuring_raster, const FrustumSensor& sensor,
                        const VisibilityGraph& graph, const SegmentCost& segment_cost,
                        const JogRemoval& jog_removal, double max_jog_shift, WaypointRoute* route) {
  CoveragePlan& plan = run.plan;
  // Patches run along the route area's boundary: the planned parts and the gaps between
  // them, whose necks the exact offset's reachable area holds too.
  const UnseenAreaRepair repair(std::move(measuring_raster), run.free_area,
                                run.options.wall_distance, {plan.route_area}, sensor, graph,
                                segment_cost);
  // Jogs whose removal shifted a lane off what it had to see are put back first: near
  // a wall that the lane's footprint reaches exactly, any shift inward leaves a band.
  std::size_t jogs_restored = 0;
  UnseenAreaRepair::Unseen unseen = repair.unseen(route->waypoints);
  if (!unseen.samples.empty()) {
    const double reach = 0.5 * std::hypot(sensor.width(), sensor.length()) + max_jog_shift;
    std::vector<bool> pinned(route->path.size(), false);
    for (std::size_t i = 0; i < route->path.size(); ++i) {
      for (const Point2& p : unseen.samples) {
        if ((p - route->path[i]).norm() <= reach) {
          pinned[i] = true;
          break;
        }
      }
    }
    std::vector<bool> pinned_kept;
    const std::vector<Point2> with_jogs =
        simplifiedPath(jog_removal.apply(route->path, route->keep, &pinned_kept, &pinned),
                       pinned_kept, route->duplicate_tolerance);
    UnseenAreaRepair::Unseen with_jogs_unseen = repair.unseen(with_jogs);
    if (with_jogs_unseen.area_m2 < unseen.area_m2) {
      jogs_restored = with_jogs.size() - std::min(with_jogs.size(), route->waypoints.size());
      route->waypoints = with_jogs;
      markInsideEnds(run, offset, route->waypoints);
      unseen = std::move(with_jogs_unseen);
    }
  }
  RepairedPath repaired = repair.repair(std::move(unseen), plan.first_inside, plan.last_inside);
  std::vector<bool> protect(repaired.waypoints.size(), false);
  protect.front() = protect.back() = true;
  protect[plan.first_inside] = protect[repaired.last_inside] = true;
  route->waypoints = simplifiedPath(repaired.waypoints, protect, route->duplicate_tolerance);
  markInsideEnds(run, offset, route->waypoints);
  std::ostringstream summary;
  summary << jogs_restored << " jog waypoints restored, " << repaired.patches
          << " patches, unseen reachable area " << repaired.unseen_before_m2 << " -> "
          << repaired.unseen_after_m2 << " m^2 of " << repaired.reachable_m2 << " m^2; ";
  return summary.str();
}

}  // namespace

CoveragePlanner::CoveragePlanner(PlanningOptions options) : options_(std::move(options)) {}

CoveragePlanner::CoveragePlanner(const PlannerParameters& parameters)
    : CoveragePlanner(planningOptionsOf(parameters)) {}

CoveragePlan CoveragePlanner::plan(const PolygonWithHoles& free_area, const Point2& start,
                                   const Point2& goal, const StageCallback& on_stage) const {
  return planParts(free_area, nullptr, start, goal, on_stage);
}

CoveragePlan CoveragePlanner::planRegion(const PolygonWithHoles& free_area,
                                         const std::vector<PolygonWithHoles>& coverage_region,
                                         const Point2& start, const Point2& goal,
                                         const StageCallback& on_stage) const {
  return planParts(free_area, &coverage_region, start, goal, on_stage);
}

CoveragePlan CoveragePlanner::planParts(const PolygonWithHoles& free_area,
                                        const std::vector<PolygonWithHoles>* coverage_region,
                                        const Point2& start, const Point2& goal,
                                        const StageCallback& on_stage) const {
  const Clock::time_point planning_start = Clock::now();
  CoveragePlan plan;
  double scale = 1.0;
  for (const Point2& p : free_area.hull) scale = std::max(scale, p.cwiseAbs().maxCoeff());
  const PlanningRun run{
      options_, free_area, start, goal, on_stage, plan, kRelativeInsideTolerance * scale};

  const OffsetStage offset = offsetStage(run);
  // The parts to cover: the planned parts of the offset free area, or their parts inside
  // the region.
  const std::vector<PolygonWithHoles> parts =
      coverage_region == nullptr ? offset.planned_parts
                                 : regionStage(run, offset.planned_parts, *coverage_region);

  // A stage that fails from here on failed on valid input (a bug), unless the input is
  // over a size limit.
  const char* failing_stage = "simplify";
  try {
    const FrustumSensor sensor = options_.frustumSensor();
    // Joined before `sensor` goes out of scope, even when a stage throws.
    std::future<ExactOffsetStage> exact_offset =
        exactOffsetInBackground(run, offset, sensor, coverage_region);
    const double simplification = options_.boundary_simplification;
    const std::vector<PolygonWithHoles> simplified = simplifyStage(run, parts, simplification);
    const DecomposedParts decomposed{parts, simplified};

    failing_stage = "decompose";
    const CellJoining joining =
        appliedCellJoining(options_.decomposition_type, options_.cell_joining);
    const std::vector<Decomposition> decompositions = decomposeStage(run, simplified, joining);

    const Clock::time_point sweeps_start = Clock::now();
    failing_stage = "sweeps";
    const SegmentCost segment_cost = options_.segmentCost();
    const VisibilityGraph graph = routeGraph(plan.route_area, segment_cost, options_);
    Tour tour;
    tour.sweeps = sweepStage(run, sweeps_start, decomposed, decompositions, sensor, graph);

    failing_stage = "transitions";
    TransitionCosts transitions = transitionStage(run, tour.sweeps, offset, graph, segment_cost);

    failing_stage = "solve";
    tour.solution = solveStage(run, std::move(transitions));
    if (joining == CellJoining::kLongestOverlap) {
      failing_stage = "alternative";
      chosetAlternativeStage(run, parts, offset, sensor, graph, segment_cost, &tour);
    }

    Clock::time_point t = Clock::now();
    failing_stage = "path";
    // Jogs shorter than a turning radius would stay sharp turns in smoothing; a shift within
    // half the lateral overlap keeps what the neighbouring lanes rely on seen.
    const double max_jog_shift = 0.5 * (sensor.width() - sensor.sweepDistance());
    const JogRemoval jog_removal(graph, options_.vehicle.turning_radius, max_jog_shift);
    WaypointRoute route =
        pathStage(run, offset, tour.sweeps, tour.solution, graph, jog_removal, scale);
    const SegmentCost time_cost(CostFunction::kTime, options_.vehicle);
    run.stage("path", t, pathSummary(route.waypoints, time_cost));

    ExactOffsetStage exact = exact_offset.get();
    plan.exact_offset_parts = std::move(exact.exact_offset_parts);
    if (exact.measuring_raster) {
      t = Clock::now();
      failing_stage = "repair";
      const std::string repaired =
          repairStage(run, offset, std::move(*exact.measuring_raster), sensor, graph, segment_cost,
                      jog_removal, max_jog_shift, &route);
      run.stage("repair", t, repaired + pathSummary(route.waypoints, time_cost));
    }
    plan.waypoints = legHeadingPoses(route.waypoints);
    plan.path_length_m = pathLength(route.waypoints);
    plan.time_cost_s = time_cost.pathCost(route.waypoints);
  } catch (const SizeLimitError&) {
    throw;
  } catch (const InvalidInputError& error) {
    throw InternalError(failing_stage, error.what());
  }
  plan.planning_time_s = secondsSince(planning_start);
  return plan;
}

}  // namespace kinematic_coverage::core
