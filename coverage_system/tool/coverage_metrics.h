#pragma once

#include "coverage_system/tool/json_object.h"
#include "trajectory_generation_tools/coverage/coverage_evaluator.h"

namespace kinematic_coverage::core {

/// Sets `coverage_percent`, `coverage_loss_percent`, `reachable_coverage_percent`,
/// `unseen_reachable_area_m2` and `unreachable_area_m2` of metrics.json
/// (docs/REFERENCE.md, Metrics): the same keys from plan, replan, evaluate and simulate.
void setCoverageMetrics(const CoverageReport& report, JsonObject& metrics);

}  // namespace kinematic_coverage::core
