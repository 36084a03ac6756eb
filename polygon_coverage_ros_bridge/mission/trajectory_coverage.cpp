#include "polygon_coverage_ros_bridge/mission/trajectory_coverage.h"

#include <chrono>
#include <sstream>

#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"

namespace kinematic_coverage::core {

TrajectoryCoverage measureTrajectoryCoverage(const PolygonWithHoles& free_area,
                                             const std::vector<PolygonWithHoles>& offset_parts,
                                             const PlannerParameters& parameters,
                                             const std::vector<Pose2>& poses) {
  const auto start = std::chrono::steady_clock::now();
  const FrustumSensor sensor = FrustumSensor::fromParameters(parameters);
  const CoverageEvaluator evaluator(free_area, offset_parts, sensor, reportingResolution(),
                                    kReportingGridAngle);
  TrajectoryCoverage coverage;
  coverage.report = evaluator.report(evaluator.seeTrajectory(poses));
  coverage.cell_size_m = evaluator.raster().cellSize();
  // The heatmap on a grid along the map's axes, as plots draw it.
  RasterResolution drawing;
  drawing.min_cell_size = kReportingCellSize;
  SeenArea seen(CoverageRaster::covering(free_area, drawing));
  seen.addTrajectory(poses, sensor);
  coverage.heatmap = seen.heatmap();
  coverage.duration_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return coverage;
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

void setCoverageMetrics(const CoverageReport& report, JsonObject& metrics) {
  metrics.set("coverage_percent", report.coverage_percent)
      .set("coverage_loss_percent", report.coverage_loss_percent)
      .set("reachable_coverage_percent", report.reachable_coverage_percent)
      .set("unseen_reachable_area_m2", report.unseen_reachable_area_m2)
      .set("unreachable_area_m2", report.unreachable_area_m2);
}

}  // namespace kinematic_coverage::core
