#pragma once

#include <array>
#include <string>
#include <utility>

#include "coverage_system/parameters/map_projection.h"
#include "polygon_coverage_ros_bridge/decomposition/sweep_line_decomposition.h"
#include "polygon_coverage_ros_bridge/geometry/internal_error.h"
#include "polygon_coverage_ros_bridge/route/offset_part_joiner.h"
#include "polygon_coverage_ros_bridge/route/segment_cost.h"
#include "polygon_coverage_ros_bridge/sweeps/sensor_options.h"
#include "trajectory_generation_tools/replanning/remaining_area_options.h"
#include "trajectory_generation_tools/simulation/robot_model.h"
#include "trajectory_generation_tools/smoothing/smoothing_strategy.h"
#include "trajectory_generation_tools/trajectory/trajectory_options.h"

namespace kinematic_coverage::core {

/// The names of a name-valued parameter (docs/REFERENCE.md, Parameters) and the stage
/// option each stands for: the one list of them, which both the parameter schema (the
/// names allowed) and the mapping to stage options read.
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
inline constexpr ParameterChoices<TrackingController, 4> kTrackingControllers{
    {{"los", TrackingController::kLos},
     {"pose_stream", TrackingController::kPoseStream},
     {"setpoint", TrackingController::kSetpoint},
     {"timed", TrackingController::kTimed}}};
inline constexpr ParameterChoices<MapProjection, 2> kMapProjections{
    {{"local", MapProjection::kLocal}, {"utm", MapProjection::kUtm}}};
inline constexpr ParameterChoices<ReplanningMethod, 3> kReplanningMethods{
    {{"convex_hull", ReplanningMethod::kConvexHull},
     {"concave_hull", ReplanningMethod::kConcaveHull},
     {"footprint", ReplanningMethod::kFootprint}}};

/// The option that `value` names, one of `choices` (checked against the parameter schema
/// before). Throws InternalError for a name that is not one of them.
template <typename Value, std::size_t N>
Value choiceOf(const std::string& value, const ParameterChoices<Value, N>& choices) {
  for (const auto& [choice_name, choice] : choices) {
    if (value == choice_name) return choice;
  }
  throw InternalError("parameters", "'" + value + "' names no option");
}

/// The name of `value` among `choices`, for log lines. Throws InternalError for a value
/// none of them names.
template <typename Value, std::size_t N>
const char* nameOf(Value value, const ParameterChoices<Value, N>& choices) {
  for (const auto& [choice_name, choice] : choices) {
    if (value == choice) return choice_name;
  }
  throw InternalError("parameters", "an option without a name");
}

}  // namespace kinematic_coverage::core
