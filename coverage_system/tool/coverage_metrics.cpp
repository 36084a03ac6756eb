#include "coverage_system/tool/coverage_metrics.h"

namespace kinematic_coverage::core {

void setCoverageMetrics(const CoverageReport& report, JsonObject& metrics) {
  metrics.set("coverage_percent", report.coverage_percent)
      .set("coverage_loss_percent", report.coverage_loss_percent)
      .set("reachable_coverage_percent", report.reachable_coverage_percent)
      .set("unseen_reachable_area_m2", report.unseen_reachable_area_m2)
      .set("unreachable_area_m2", report.unreachable_area_m2);
}

}  // namespace kinematic_coverage::core
