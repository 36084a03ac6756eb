#pragma once

#include <string>
#include <vector>

#include "coverage_system/mission/mission.h"
#include "coverage_system/planner/coverage_planner.h"

namespace kinematic_coverage::core {

/// A mission planned end to end, with what every consumer reports.
struct PlannedMission {
  /// The cleaned free area the plan was made for (collision checks use it).
  PolygonWithHoles free_area;
  /// The plan; its stages start with "validate" and "clean".
  CoveragePlan plan;
  /// Cleaning warnings first, then the planner's.
  std::vector<std::string> warnings;
  /// Validation, cleaning and planning, seconds.
  double planning_time_s = 0.0;
};

/// Validates the mission's polygon, start and goal (docs/REFERENCE.md, Geometry and input
/// rules), cleans the polygon and plans it: the one sequence that coverage_tool, the nodes
/// and the benchmarks share. `on_stage`, when given, hears of every stage as it finishes.
/// Throws InvalidInputError for invalid input or an impossible request.
PlannedMission planMission(const Mission& mission, const StageCallback& on_stage = {});

}  // namespace kinematic_coverage::core
