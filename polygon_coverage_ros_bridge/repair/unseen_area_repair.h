#pragma once

#include <Eigen/Geometry>
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/nearest_segment_index.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "polygon_coverage_ros_bridge/repair/exact_offset_excursions.h"
#include "polygon_coverage_ros_bridge/route/segment_cost.h"
#include "polygon_coverage_ros_bridge/route/visibility_graph.h"
#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"
#include "trajectory_generation_tools/coverage/coverage_evaluator.h"

namespace kinematic_coverage::core {

/// A waypoint path after UnseenAreaRepair, with what the repair measured.
struct RepairedPath {
  std::vector<Point2> waypoints;
  /// The index of the last waypoint inside the offset free area (moved by the insertions).
  std::size_t last_inside = 0;
  /// Patches driven: stretches along the boundary or through an unseen region.
  std::size_t patches = 0;
  /// The reachable area, and the part of it that the path left unseen before and after.
  double reachable_m2 = 0.0;
  double unseen_before_m2 = 0.0;
  double unseen_after_m2 = 0.0;
};

/// Search safety of the planner's waypoint path: sweeps planned cell by cell can leave
/// reachable area unseen (a band along a side steeper than the lanes' flanks, the rim of a
/// cell corner), and the object may lie there. The repair measures the path's footprints
/// on the coverage report's raster, and for every unseen region of the reachable area
/// drives a patch that sees it: along the offset free area's boundary beside it (where a
/// band lies beyond the boundary, or within a quarter footprint width inside it), out of
/// a corner of the boundary toward the round corner of the exact offset (ExactOffsetExcursions,
/// where that passes nearer the region than the boundary does), or through it (deeper
/// inside); each patch is driven where the detour costs least, as a
/// spur from the path, instead of a leg whose view the path keeps, or (an excursion) as a
/// bump that bends a leg out through its far end (a round of patches that loses what the
/// path saw is tried again with spurs only, which keep every leg).
/// Rounds repeat while unseen regions remain and the last round saw more.
class UnseenAreaRepair {
 public:
  /// `free_area` (cleaned) and `planned_parts` (the parts of the offset free area by
  /// `wall_distance` that the path covers) define the reachable area: the exact offset
  /// around the parts (exactOffsetParts), grown by half a footprint length; `graph` routes
  /// inside the area the path runs in (it must outlive this object); `segment_cost` prices
  /// the detours as the planner's generalized TSP does. With `coverage_region` (a replanned
  /// mission's remaining area), only the reachable area inside it counts: the rest was seen
  /// before.
  UnseenAreaRepair(const PolygonWithHoles& free_area, double wall_distance,
                   std::vector<PolygonWithHoles> planned_parts, const FrustumSensor& sensor,
                   const VisibilityGraph& graph, const SegmentCost& segment_cost,
                   const std::vector<PolygonWithHoles>* coverage_region = nullptr);

  /// The repair with the raster that measuringRaster() built (so that a planner can build
  /// it while its earlier stages run); `patch_areas` are where the patches run (a planner
  /// passes its route area: the planned parts joined through their gaps).
  UnseenAreaRepair(CoverageEvaluator measuring_raster, const PolygonWithHoles& free_area,
                   double wall_distance, std::vector<PolygonWithHoles> patch_areas,
                   const FrustumSensor& sensor, const VisibilityGraph& graph,
                   const SegmentCost& segment_cost);

  /// The raster on which the repair measures a path: the coverage report's, with the
  /// reachable area of `free_area` grown from `exact_parts` (the exact offset around the
  /// planned parts, exactOffsetParts), inside `coverage_region`, if given.
  static CoverageEvaluator measuringRaster(const PolygonWithHoles& free_area,
                                           const std::vector<PolygonWithHoles>& exact_parts,
                                           const FrustumSensor& sensor,
                                           const std::vector<PolygonWithHoles>* coverage_region);

  /// The path with its patches. Only legs between `first_inside` and `last_inside` (the
  /// waypoints inside the offset free area) get patches; start and goal stay.
  RepairedPath repair(std::vector<Point2> waypoints, std::size_t first_inside,
                      std::size_t last_inside) const;

  /// What a waypoint path leaves unseen of the reachable area.
  struct Unseen {
    double area_m2 = 0.0;
    /// Cells of the regions that the repair would patch (up to 400 spread over each): where
    /// the planner puts back waypoints that its jog removal shifted, which sees a band
    /// along a wall for far less than a patch does.
    std::vector<Point2> samples;
    /// The measurement behind them: what the path sees, and every unseen region, the
    /// largest first (repair starts from it instead of measuring the path again).
    std::vector<Point2> waypoints;
    std::optional<SeenArea> seen;
    std::vector<UnseenRegion> regions;
  };

  /// Measures what `waypoints` leave unseen.
  Unseen unseen(const std::vector<Point2>& waypoints) const;

  /// repair() of the path that `measured` (unseen()) measured, without measuring it again.
  RepairedPath repair(Unseen measured, std::size_t first_inside, std::size_t last_inside) const;

 private:
  /// A point of a boundary ring of the planned parts: the ring, the edge it lies on and
  /// the arc length to it.
  struct RingPosition {
    std::size_t ring = 0;
    std::size_t edge = 0;
    double arc_length = 0.0;
  };

  /// The nearest point of the planned parts' boundary to p, with its ring position.
  RingPosition nearestOnBoundary(const Point2& p, double* distance) const;

  /// True when p lies in one of the patch areas.
  bool inPatchAreas(const Point2& p) const;

  /// The point of ring `ring` at `arc_length` from its first vertex.
  Point2 pointAt(std::size_t ring, double arc_length) const;

  /// The patches that see the region of which `samples` are cells.
  std::vector<std::vector<Point2>> patchesFor(const std::vector<Point2>& samples) const;

  /// A sample of an unseen region with its nearest boundary point and the distance to it.
  struct BoundarySample {
    Point2 point;
    RingPosition position;
    double distance = 0.0;
  };

  /// Out of the samples beyond the patch areas, those that an excursion (from a corner of
  /// the edges they lie beside, or toward the farthest of them) passes nearer than the
  /// boundary: they are removed from `beyond`, and the excursions that see them are
  /// returned as patches out and back.
  std::vector<std::vector<Point2>> excursionPatches(std::vector<BoundarySample>* beyond) const;

  /// The stretch of ring `ring` from `from` to `to` (arc lengths, forward, may wrap).
  std::vector<Point2> boundaryWalk(std::size_t ring, double from, double to) const;

  /// The legs of `path` between `first_inside` and `last_inside` nearest to the patch's
  /// ends (kCandidateLegs of them), not those out of the area that the graph routes in (an
  /// excursion's).
  std::vector<std::size_t> nearestLegs(const std::vector<Point2>& patch,
                                       const std::vector<Point2>& path, std::size_t first_inside,
                                       std::size_t last_inside) const;

  /// A way through an excursion's far end instead of out and back: the middle of a leg,
  /// from `leave` to `rejoin`, replaced by straight ways out to the far end and back that
  /// keep the wall distance; `cost` is what it adds to the leg's.
  struct Bump {
    double cost = 0.0;
    Point2 leave;
    Point2 rejoin;
  };

  /// The widest bump of the leg from a to b through `apex` that keeps the distance, if any.
  std::optional<Bump> bump(const Point2& apex, const Point2& a, const Point2& b) const;

  /// Which legs a patch's detour may replace instead of leaving them as they are.
  enum class LegReplacement { kAnyLeg, kUnneededLeg, kNone };

  /// Where and how a patch joins the path, with what that adds to its cost: after waypoint
  /// `leg`, as a spur from `anchor`, a detour instead of the leg (no anchor), or a bump.
  struct Insertion {
    double cost = std::numeric_limits<double>::infinity();
    std::size_t leg = 0;
    std::optional<Point2> anchor;
    bool reversed = false;  ///< the patch driven from its back to its front
    std::optional<Bump> bump;
  };

  /// The cheapest insertion of `patch` at one of `legs` of `path` that `replacement` allows
  /// (legNeeded on the path's `view`); an infinite cost when none can reach it.
  Insertion cheapestInsertion(const std::vector<Point2>& patch, LegReplacement replacement,
                              const SeenArea& view, const std::vector<std::size_t>& legs,
                              const std::vector<Point2>& path,
                              VisibilityGraph::PointCache* routes) const;

  /// The points that `insertion` puts after its leg's first waypoint (none when the patch
  /// adds nothing to the path).
  std::vector<Point2> insertedPoints(const Insertion& insertion, const std::vector<Point2>& patch,
                                     const std::vector<Point2>& path,
                                     VisibilityGraph::PointCache* routes) const;

  /// Inserts `patch` where cheapestInsertion puts it; false when no leg can reach the patch.
  /// `routes` keeps the points priced so far.
  bool insert(const std::vector<Point2>& patch, LegReplacement replacement, const SeenArea& view,
              std::size_t first_inside, std::size_t* last_inside, std::vector<Point2>* waypoints,
              VisibilityGraph::PointCache* routes) const;

  /// True unless every reachable cell sampled in the middle of the leg's view was seen at
  /// least twice (by another step of the path too).
  bool legNeeded(const SeenArea& seen, const Point2& a, const Point2& b) const;

  std::vector<PolygonWithHoles> patch_areas_;
  FrustumSensor sensor_;
  /// The coverage report's raster with the reachable area's rim measured exactly (only
  /// its part inside the coverage region, if one was given).
  CoverageEvaluator evaluator_;
  const VisibilityGraph& graph_;
  SegmentCost segment_cost_;
  double min_region_m2_;  ///< smaller unseen regions get no patch
  double join_distance_;  ///< unseen cells closer than this are one region
  ExactOffsetExcursions excursions_;
  std::vector<Ring> rings_;  ///< every hull and hole of the parts, the parts to their left
  std::vector<std::vector<double>> arc_lengths_;  ///< per ring, to each vertex and round
  /// The rings' edges (none without patch areas), and the ring and edge of each.
  std::optional<NearestSegmentIndex> boundary_index_;
  std::vector<std::pair<std::size_t, std::size_t>> boundary_edges_;
  std::vector<Eigen::AlignedBox2d> part_boxes_;  ///< the patch areas' bounding boxes
};

}  // namespace kinematic_coverage::core
