#pragma once

#include <optional>
#include <string>
#include <vector>

#include "coverage_system/parameters/planner_parameters.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/coverage/coverage_evaluator.h"

namespace kinematic_coverage::core {

/// The coverage of one trajectory as coverage_tool reports it, and how it was measured.
struct TrajectoryCoverage {
  CoverageReport report;
  double cell_size_m = 0.0;  ///< edge of the raster's square cells
  double duration_s = 0.0;   ///< rasterizing the areas, seeing the poses and the report
  Heatmap heatmap;           ///< separate visits per cell, for plot.png
  /// The largest piece of the reachable area never seen; none when all of it was seen.
  std::optional<UnseenRegion> largest_unseen_region;
  /// What the trajectory fails to see of what a reference trajectory sees (its unsmoothed
  /// one); none without a reference.
  std::optional<LostArea> lost_to_reference;
};

/// The share of the reachable area (percent) below which a trajectory leaves area it
/// could search unseen, and `plan` says so.
constexpr double kReachableCoverageBarPercent = 99.9;

/// Measures the coverage of a trajectory's sampled `poses` over a
/// mission's cleaned free area, with the sensor that `parameters` describe, on the raster
/// of reportingResolution() turned by kReportingGridAngle: the one measurement behind
/// `plan`'s figures for its own trajectory and `evaluate`'s for any trajectory file, so
/// that both agree on the same poses. `exact_parts` (the parts of the exact offset that the
/// robot reaches, exactOffsetParts: a plan's exact_offset_parts) only shape the reachable
/// area, every point at least the wall distance from the walls grown by half a footprint. The
/// heatmap is the turned raster's visits read at the cell centres of a grid along the map's axes
/// (cells of 5 cm or coarser), as plots draw it. With `reference` poses (the unsmoothed trajectory
/// of the same waypoints), also what `poses` fail to see of what they see, on the same raster.
/// Throws InvalidInputError for a non-finite pose, an invalid sensor or an offset free area that
/// covers no cell.
TrajectoryCoverage measureTrajectoryCoverage(
    const PolygonWithHoles& free_area, const std::vector<PolygonWithHoles>& exact_parts,
    const PlannerParameters& parameters, const std::vector<Pose2>& poses,
    const std::optional<std::vector<Pose2>>& reference = std::nullopt);

/// A warning when the trajectory sees less than kReachableCoverageBarPercent of the
/// reachable area, naming the unseen area and the largest unseen region (its area and
/// centroid); none otherwise.
std::optional<std::string> reachableCoverageWarning(const TrajectoryCoverage& coverage);

/// Smoothing lets the sensor see less than the unsmoothed trajectory where its strategy does
/// not guard the area (beyond the reachable area, unless coverage_safe_area: free) or within
/// the coverage-safe tolerance: a warning when the trajectory fails to see more than this
/// share of the free area (percent) that its unsmoothed trajectory sees.
constexpr double kSmoothingLossWarningPercent = 0.1;

/// A warning when `coverage.lost_to_reference` (the smoothed trajectory against its
/// unsmoothed one) exceeds kSmoothingLossWarningPercent of the free area, naming the area
/// and its reachable part; none otherwise.
std::optional<std::string> smoothingLossWarning(const TrajectoryCoverage& coverage);

/// The summary of a coverage stage's progress line, e.g. "99.977 % of the free area seen
/// (coverage loss 0.023 %), 100 % of the reachable area, 5 cm cells".
std::string coverageSummary(const TrajectoryCoverage& coverage);

}  // namespace kinematic_coverage::core
