#pragma once

#include <array>
#include <string>
#include <utility>

#include "polygon_coverage_ros_bridge/decomposition/sweep_line_decomposition.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/route/offset_part_joiner.h"
#include "polygon_coverage_ros_bridge/route/segment_cost.h"
#include "polygon_coverage_ros_bridge/sweeps/sensor_options.h"
#include "trajectory_generation_tools/replanning/remaining_area_options.h"
#include "trajectory_generation_tools/simulation/robot_model.h"
#include "trajectory_generation_tools/smoothing/smoothing_strategy.h"
#include "trajectory_generation_tools/trajectory/trajectory_options.h"

namespace kinematic_coverage::core {

/// The names of a name-valued parameter (docs/REFERENCE.md, Parameters) and the stage
/// option each stands for: the one list of them, which both the range check and the
/// mapping to stage options read.
template <typename Value, std::size_t N>
using ParameterChoices = std::array<std::pair<const char*, Value>, N>;

inline constexpr ParameterChoices<DecompositionType, 2> kDecompositionTypes{
    {{"boustrophedon", DecompositionType::kBoustrophedon},
     {"trapezoidal", DecompositionType::kTrapezoidal}}};
inline constexpr ParameterChoices<CellJoining, 2> kCellJoinings{
    {{"critical_points", CellJoining::kAtCriticalPoints},
     {"longest_overlap", CellJoining::kLongestOverlap}}};
inline constexpr ParameterChoices<CostFunction, 3> kCostFunctions{
    {{"distance", CostFunction::kDistance},
     {"time", CostFunction::kTime},
     {"waypoints", CostFunction::kWaypoints}}};
inline constexpr ParameterChoices<OffsetParts, 2> kOffsetParts{
    {{"all", OffsetParts::kAll}, {"largest", OffsetParts::kLargest}}};
inline constexpr ParameterChoices<SensorModel, 2> kSensorModels{
    {{"frustum", SensorModel::kFrustum}, {"line", SensorModel::kLine}}};
inline constexpr ParameterChoices<SmoothingStrategy, 3> kSmoothingStrategies{
    {{"coverage_safe", SmoothingStrategy::kCoverageSafe},
     {"global", SmoothingStrategy::kGlobal},
     {"local", SmoothingStrategy::kLocal}}};
inline constexpr ParameterChoices<CoverageSafeArea, 2> kCoverageSafeAreas{
    {{"free", CoverageSafeArea::kFree}, {"reachable", CoverageSafeArea::kReachable}}};
inline constexpr ParameterChoices<TurnCurve, 2> kTurnCurves{
    {{"arc", TurnCurve::kArc}, {"clothoid", TurnCurve::kClothoid}}};
inline constexpr ParameterChoices<VehicleModel, 2> kVehicleModels{
    {{"dynamic", VehicleModel::kDynamic}, {"kinematic", VehicleModel::kKinematic}}};
inline constexpr ParameterChoices<ReplanningMethod, 3> kReplanningMethods{
    {{"convex_hull", ReplanningMethod::kConvexHull},
     {"concave_hull", ReplanningMethod::kConcaveHull},
     {"footprint", ReplanningMethod::kFootprint}}};

/// The option that parameter `name`'s `value` names. Throws InvalidInputError naming the
/// parameter, the value and the names allowed, e.g. "sensor_model = 'sonar' is not one of:
/// frustum, line".
template <typename Value, std::size_t N>
Value choiceOf(const char* name, const std::string& value,
               const ParameterChoices<Value, N>& choices) {
  std::string list;
  for (const auto& [choice_name, choice] : choices) {
    if (value == choice_name) return choice;
    list += (list.empty() ? "" : ", ") + std::string(choice_name);
  }
  throw InvalidInputError(std::string(name) + " = '" + value + "' is not one of: " + list);
}

}  // namespace kinematic_coverage::core
