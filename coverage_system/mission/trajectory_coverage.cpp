#include "coverage_system/mission/trajectory_coverage.h"

#include <chrono>
#include <sstream>

#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/base/elapsed_seconds.h"
#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"

namespace kinematic_coverage::core {

TrajectoryCoverage measureTrajectoryCoverage(const PolygonWithHoles& free_area,
                                             const std::vector<PolygonWithHoles>& exact_parts,
                                             const PlannerParameters& parameters,
                                             const std::vector<Pose2>& poses,
                                             const std::optional<std::vector<Pose2>>& reference) {
  const auto start = std::chrono::steady_clock::now();
  const FrustumSensor sensor = sensorOf(parameters);
  const CoverageEvaluator evaluator(free_area, exact_parts, sensor, reportingResolution(),
                                    kReportingGridAngle);
  TrajectoryCoverage coverage;
  const SeenArea seen_reported = evaluator.seeTrajectory(poses);
  coverage.report = evaluator.report(seen_reported);
  coverage.largest_unseen_region = evaluator.largestUnseenRegion(seen_reported);
  if (reference) {
    coverage.lost_to_reference =
        evaluator.lostArea(evaluator.seeTrajectory(*reference), seen_reported);
  }
  coverage.cell_size_m = evaluator.raster().cellSize();
  // The heatmap on a grid along the map's axes, as plots draw it, read off the turned one.
  RasterResolution drawing;
  drawing.min_cell_size = kReportingCellSize;
  coverage.heatmap =
      evaluator.heatmapOn(seen_reported, CoverageRaster::covering(free_area, drawing));
  coverage.duration_s = secondsSince(start);
  return coverage;
}

std::optional<std::string> reachableCoverageWarning(const TrajectoryCoverage& coverage) {
  const CoverageReport& report = coverage.report;
  if (report.reachable_coverage_percent >= kReachableCoverageBarPercent) return std::nullopt;
  std::ostringstream out;
  out.precision(5);
  out << "the trajectory sees " << report.reachable_coverage_percent
      << " % of the reachable area, less than " << kReachableCoverageBarPercent
      << " %: " << report.unseen_reachable_area_m2 << " m^2 of it unseen";
  if (const std::optional<UnseenRegion>& region = coverage.largest_unseen_region) {
    out.precision(4);
    out << ", the largest unseen region " << region->area_m2 << " m^2 around ("
        << region->centroid.x() << ", " << region->centroid.y() << ")";
  }
  return out.str();
}

std::optional<std::string> smoothingLossWarning(const TrajectoryCoverage& coverage) {
  const std::optional<LostArea>& lost = coverage.lost_to_reference;
  if (!lost || lost->percent_of_free_area <= kSmoothingLossWarningPercent) return std::nullopt;
  std::ostringstream out;
  out.precision(4);
  out << "smoothing loses " << lost->area_m2 << " m^2 (" << lost->percent_of_free_area
      << " % of the free area) that the unsmoothed trajectory sees, " << lost->reachable_area_m2
      << " m^2 of it in the reachable area and the rest beyond it; coverage_safe_area: free "
         "(with smoothing_strategy: coverage_safe) or smoothing: false keeps it";
  return out.str();
}

std::string coverageSummary(const TrajectoryCoverage& coverage) {
  std::ostringstream out;
  out.precision(5);
  out << coverage.report.coverage_percent << " % of the free area seen (coverage loss "
      << coverage.report.coverage_loss_percent << " %), "
      << coverage.report.reachable_coverage_percent << " % of the reachable area ("
      << coverage.report.unseen_reachable_area_m2 << " m^2 of it unseen), "
      << 100.0 * coverage.cell_size_m << " cm cells";
  return out.str();
}

}  // namespace kinematic_coverage::core
