// An independent coverage oracle for the tests: the seen, free and reachable areas of
// docs/REFERENCE.md, Sensor footprint and coverage, computed as exact polygons with CGAL's
// Boolean set operations (Epeck kernel) instead of on a raster. It shares no code with
// trajectory_generation_tools/coverage/ (the raster evaluator it checks) nor with the
// planner's wall offset (polygon_coverage_ros_bridge/geometry/wall_offset*): it takes only
// the package's plain data types as input and builds every footprint, hull, erosion and
// dilation itself.
#pragma once

#include <memory>
#include <vector>

#include "coverage_system/parameters/planner_parameters.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {
namespace testing {

/// The footprint rectangle of docs/REFERENCE.md, Sensor footprint and coverage: `width`
/// across the heading, `length` along it (0 for a line sensor: a segment).
struct OracleFootprint {
  double width = 0.0;
  double length = 0.0;
};

/// W = 2 d tan(lateral_fov / 2), L = 2 d tan(onward_fov / 2) for a frustum sensor at
/// d = sensor_distance; W = lateral_footprint, L = 0 for a line sensor.
OracleFootprint oracleFootprint(const PlannerParameters& parameters);

/// What the oracle measures of one trajectory, in square metres and percent.
struct ExactCoverage {
  double free_area_m2 = 0.0;                ///< area(F)
  double reachable_area_m2 = 0.0;           ///< area(R)
  double seen_free_area_m2 = 0.0;           ///< area(seen ∩ F)
  double seen_reachable_area_m2 = 0.0;      ///< area(seen ∩ R)
  double coverage_percent = 0.0;            ///< 100 area(seen ∩ F) / area(F)
  double reachable_coverage_percent = 0.0;  ///< 100 area(seen ∩ R) / area(R)
};

/// Error bounds of the reachable area R (which is polygonal where the definition has
/// circular arcs), square metres; see exact_coverage_oracle.cpp for their derivation.
struct ReachableAreaErrorBound {
  /// area(E_w) - area(E) for the eroded free area E (a subset of the exact E_w).
  double erosion_m2 = 0.0;
  /// area(E (+) disk) - area(E (+) polygon) for the dilation of the computed E.
  double dilation_m2 = 0.0;
};

/// How another offset free area (the planner's, say) differs from the oracle's, m^2.
struct OffsetFreeAreaDifference {
  double missing_m2 = 0.0;  ///< area(E minus other): in the oracle's E only
  double extra_m2 = 0.0;    ///< area(other minus E): in the other only
};

/// The exact coverage figures of trajectories over one free area.
class ExactCoverageOracle {
 public:
  /// Prepares F (the cleaned free area: a simple hull and disjoint simple holes inside it,
  /// either orientation), the offset free area E (points of F at least `wall_distance`
  /// from the hull and from every hole) and the reachable area R (points of F within
  /// footprint.length / 2 of E); the disks of the erosion and the dilation are regular
  /// polygons with `disk_sides` sides.
  ExactCoverageOracle(const PolygonWithHoles& free_area, double wall_distance,
                      const OracleFootprint& footprint, int disk_sides = 256);
  /// As above with the offset free area E given (the planner's, say; clipped to F) rather
  /// than eroded from F: R is then E grown by the oracle's own dilation, for checking how a
  /// reachable area defined by that polygon is measured. The erosion bound is then 0.
  ExactCoverageOracle(const PolygonWithHoles& free_area,
                      const std::vector<PolygonWithHoles>& offset_parts,
                      const OracleFootprint& footprint, int disk_sides = 256);
  ~ExactCoverageOracle();
  ExactCoverageOracle(const ExactCoverageOracle&) = delete;
  ExactCoverageOracle& operator=(const ExactCoverageOracle&) = delete;

  double freeAreaM2() const;
  double offsetFreeAreaM2() const;
  double reachableAreaM2() const;
  /// Connected parts of the offset free area E (a strait narrower than 2 wall distances
  /// splits it).
  int offsetFreeAreaParts() const;
  const ReachableAreaErrorBound& reachableErrorBound() const;
  /// The exact areas by which `other` (disjoint parts, each hull minus holes) and the
  /// oracle's E differ.
  OffsetFreeAreaDifference compareOffsetFreeArea(const std::vector<PolygonWithHoles>& other) const;

  /// The seen area of `poses` (the union of their footprints and of the convex hulls of
  /// consecutive footprints at different positions), intersected exactly with F and R.
  /// With `merge_straight_runs`, a run of poses of one heading advancing along one line
  /// (a sampled segment) counts as the hull of its first and last footprints, which is
  /// the union of its consecutive hulls (the footprint swept along the segment) up to the
  /// run's rounding; that keeps the exact union small enough for trajectories of
  /// thousands of poses.
  ExactCoverage measure(const std::vector<Pose2>& poses, bool merge_straight_runs = true) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace testing
}  // namespace kinematic_coverage::core
