#include "polygon_coverage_ros_bridge/mission/trajectory_coverage.h"

#include <chrono>
#include <sstream>

#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"

namespace kinematic_coverage::core {

TrajectoryCoverage measureTrajectoryCoverage(const PolygonWithHoles& free_area,
                                             const PolygonWithHoles& offset_free_area,
                                             const PlannerParameters& parameters,
                                             const std::vector<Pose2>& poses) {
  const auto start = std::chrono::steady_clock::now();
  const CoverageEvaluator evaluator(free_area, offset_free_area,
                                    FrustumSensor::fromParameters(parameters),
                                    reportingResolution());
  TrajectoryCoverage coverage;
  const SeenArea seen = evaluator.seeTrajectory(poses);
  coverage.report = evaluator.report(seen);
  coverage.cell_size_m = evaluator.raster().cellSize();
  coverage.duration_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  coverage.heatmap = seen.heatmap();
  return coverage;
}

std::string coverageSummary(const TrajectoryCoverage& coverage) {
  std::ostringstream out;
  out.precision(5);
  out << coverage.report.coverage_percent << " % of the free area seen (coverage loss "
      << coverage.report.coverage_loss_percent << " %), "
      << coverage.report.reachable_coverage_percent << " % of the reachable area, "
      << 100.0 * coverage.cell_size_m << " cm cells";
  return out.str();
}

void setCoverageMetrics(const CoverageReport& report, JsonObject& metrics) {
  metrics.set("coverage_percent", report.coverage_percent)
      .set("coverage_loss_percent", report.coverage_loss_percent)
      .set("reachable_coverage_percent", report.reachable_coverage_percent);
}

}  // namespace kinematic_coverage::core
