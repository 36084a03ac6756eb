#include "coverage_system/planner/replanner.h"

#include <chrono>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>

#include "coverage_system/parameters/parameter_choices.h"
#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/base/elapsed_seconds.h"
#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/validation/free_area_builder.h"

namespace kinematic_coverage::core {
namespace {

using Clock = std::chrono::steady_clock;

/// A start moved out of a hole is placed this far (relative to the map's scale) outside
/// it, so that it is not on the hole's boundary.
constexpr double kRelativeClearance = 1e-7;

/// The last visited pose, moved out of a hole that now covers it (see Replanner).
Point2 replanStart(const PolygonWithHoles& free_area, const Point2& last, double wall_distance) {
  double scale = 1.0;
  for (const Point2& p : free_area.hull) scale = std::max(scale, p.cwiseAbs().maxCoeff());
  for (std::size_t i = 0; i < free_area.holes.size(); ++i) {
    const Ring& hole = free_area.holes[i];
    if (!insideRing(last, hole)) continue;
    Point2 nearest = hole.front();
    double depth = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < hole.size(); ++k) {
      const Point2 q = closestPointOnSegment(last, hole[k], hole[(k + 1) % hole.size()]);
      if ((q - last).norm() < depth) {
        depth = (q - last).norm();
        nearest = q;
      }
    }
    if (depth > wall_distance) {
      throw InvalidInputError(
          "the last visited pose " + formatPoint(last) + " lies inside moved hole " +
          std::to_string(i) + ", " + formatNumber(depth) +
          " m from its edge: no free point within wall_distance = " + formatNumber(wall_distance) +
          " m");
    }
    const Point2 outward = depth > 0.0 ? Point2((nearest - last) / depth) : Point2::Zero();
    return nearest + kRelativeClearance * scale * outward;
  }
  return last;
}

/// The warning that names every part of the remaining area too small to replan.
std::string droppedPartsWarning(const RemainingArea& remaining, double min_area) {
  std::ostringstream out;
  out.precision(4);
  double total = 0.0;
  for (const DroppedPart& part : remaining.dropped) total += part.area_m2;
  out << remaining.dropped.size() << " parts of the remaining area (" << total
      << " m^2 together) are smaller than replanning_min_area (" << min_area
      << " m^2) and are not replanned:";
  for (std::size_t i = 0; i < remaining.dropped.size(); ++i) {
    out << (i ? "," : "") << " " << remaining.dropped[i].area_m2 << " m^2 around "
        << formatPoint(remaining.dropped[i].centroid);
  }
  return out.str();
}

}  // namespace

Replanner::Replanner(PlanningOptions planning, RemainingAreaOptions remaining)
    : planning_options_(std::move(planning)), remaining_options_(std::move(remaining)) {}

Replanner::Replanner(const PlannerParameters& parameters)
    : Replanner(planningOptionsOf(parameters), remainingAreaOptionsOf(parameters)) {}

ReplannedMission Replanner::replan(const PolygonWithHoles& updated_polygon,
                                   const std::vector<Pose2>& visited, const Point2& goal,
                                   const StageCallback& on_stage) const {
  if (visited.empty()) {
    throw InvalidInputError("no visited poses: replanning starts from the last visited pose");
  }
  return replanFrom(
      updated_polygon, visited.back(), visited.size(), goal, on_stage,
      [&](const PolygonWithHoles& free_area) {
        return RemainingAreaCalculator(remaining_options_).compute(free_area, visited);
      });
}

ReplannedMission Replanner::replan(const PolygonWithHoles& updated_polygon,
                                   const VisitedHistory& visited, const Point2& goal,
                                   const StageCallback& on_stage) const {
  if (visited.empty()) {
    throw InvalidInputError("no visited poses: replanning starts from the last visited pose");
  }
  return replanFrom(
      updated_polygon, visited.last(), visited.count(), goal, on_stage,
      [&](const PolygonWithHoles& free_area) {
        return RemainingAreaCalculator(remaining_options_).compute(free_area, visited);
      });
}

ReplannedMission Replanner::replanFrom(
    const PolygonWithHoles& updated_polygon, const Pose2& last, std::size_t visited_count,
    const Point2& goal, const StageCallback& on_stage,
    const std::function<RemainingArea(const PolygonWithHoles&)>& remaining_of) const {
  const Clock::time_point start_time = Clock::now();
  ReplannedMission result;
  std::vector<PlanningStage> stages;
  auto stage_took = [&](const std::string& name, double seconds, std::string summary) {
    stages.push_back({name, seconds, std::move(summary)});
    if (on_stage) on_stage(stages.back());
  };
  auto stage = [&](const std::string& name, Clock::time_point since, std::string summary) {
    stage_took(name, secondsSince(since), std::move(summary));
  };

  if (!std::isfinite(last.x) || !std::isfinite(last.y)) {
    throw InvalidInputError("the last visited pose has a non-finite coordinate");
  }
  BuiltFreeArea built = FreeAreaBuilder(planning_options_.boundary_simplification)
                            .build(updated_polygon, {{"goal", goal}});
  stage_took("validate", built.validate_s,
             "updated polygon and goal valid, " + std::to_string(visited_count) + " visited poses");

  Clock::time_point t = Clock::now();
  result.free_area = std::move(built.cleaned.free_area);
  result.warnings = std::move(built.cleaned.warnings);
  result.start = replanStart(result.free_area, last.position(), planning_options_.wall_distance);
  {
    std::ostringstream summary;
    summary << "free area " << area(result.free_area) << " m^2, " << result.free_area.holes.size()
            << " holes, start " << formatPoint(result.start);
    stage_took("clean", built.clean_s + secondsSince(t), summary.str());
  }

  t = Clock::now();
  result.remaining = remaining_of(result.free_area);
  {
    const RemainingArea& remaining = result.remaining;
    std::ostringstream summary;
    summary.precision(4);
    summary << nameOf(remaining_options_.method, kReplanningMethods) << ": "
            << remaining.seen_area_m2 << " m^2 seen, " << remaining.remaining_area_m2
            << " m^2 left, " << remaining.parts.size() << " parts kept (" << remaining.kept_area_m2
            << " m^2), " << remaining.dropped.size() << " small parts dropped";
    stage("remaining", t, summary.str());
    if (!remaining.dropped.empty()) {
      result.warnings.push_back(droppedPartsWarning(remaining, remaining_options_.min_area));
    }
  }

  result.plan =
      CoveragePlanner(planning_options_)
          .planRegion(result.free_area, result.remaining.parts, result.start, goal, on_stage);
  result.plan.stages.insert(result.plan.stages.begin(), stages.begin(), stages.end());
  result.warnings.insert(result.warnings.end(), result.plan.warnings.begin(),
                         result.plan.warnings.end());
  result.planning_time_s = secondsSince(start_time);
  return result;
}

}  // namespace kinematic_coverage::core
