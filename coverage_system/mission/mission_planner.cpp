#include "coverage_system/mission/mission_planner.h"

#include <chrono>
#include <sstream>

#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/base/elapsed_seconds.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/validation/free_area_builder.h"

namespace kinematic_coverage::core {
namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

PlannedMission planMission(const Mission& mission, const StageCallback& on_stage) {
  const Clock::time_point start = Clock::now();
  std::vector<PlanningStage> stages;

  BuiltFreeArea built =
      FreeAreaBuilder(boundarySimplificationOf(mission.parameters))
          .build(mission.polygon, {{"start", mission.start}, {"goal", mission.goal}});
  CleanedPolygon& cleaned = built.cleaned;
  stages.push_back({"validate", built.validate_s, "polygon, start and goal valid"});
  if (on_stage) on_stage(stages.back());

  std::ostringstream summary;
  summary << "free area " << area(cleaned.free_area) << " m^2, " << cleaned.free_area.holes.size()
          << " holes, " << cleaned.warnings.size() << " cleaning steps";
  stages.push_back({"clean", built.clean_s, summary.str()});
  if (on_stage) on_stage(stages.back());

  PlannedMission planned;
  planned.plan = CoveragePlanner(mission.parameters)
                     .plan(cleaned.free_area, mission.start, mission.goal, on_stage);
  planned.planning_time_s = secondsSince(start);
  planned.plan.stages.insert(planned.plan.stages.begin(), stages.begin(), stages.end());
  planned.warnings = std::move(cleaned.warnings);
  planned.warnings.insert(planned.warnings.end(), planned.plan.warnings.begin(),
                          planned.plan.warnings.end());
  planned.free_area = std::move(cleaned.free_area);
  return planned;
}

}  // namespace kinematic_coverage::core
