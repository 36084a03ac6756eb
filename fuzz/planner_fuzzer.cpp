// libFuzzer target: CoveragePlanner through the path `coverage_tool plan` takes
// (checkParameters as the mission loader applies it, then planMission: validate, clean,
// plan, with or without coverage_repair, decomposing the exact or a simplified boundary) on
// small fuzzed polygons with holes: at most kMaxHullVertices hull vertices and kMaxHoles holes
// of at most kMaxHoleVertices vertices, coordinates within [-5, 35] m, parameters in range or,
// now and then, deliberately out of range.
// Properties of every plan: waypoints are finite and distinct, each yaw is its leg's heading, the
// path starts at the start and ends at the goal, every leg between first_inside and last_inside
// lies in the route area (the offset free area's parts joined through their gaps; the planner
// test's tolerance) or, out of it toward the exact offset's boundary (the repair's
// excursions), keeps the wall distance, and the inside range and path
// length are consistent.

#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "coverage_system/mission/mission.h"
#include "coverage_system/mission/mission_planner.h"
#include "coverage_system/parameters/parameter_schema.h"
#include "fuzz/fuzz_check.h"
#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "test/support/sampled_wall_distance.h"

namespace {

using kinematic_coverage::core::Mission;
using kinematic_coverage::core::PlannedMission;
using kinematic_coverage::core::PlannerParameters;
using kinematic_coverage::core::Point2;
using kinematic_coverage::core::Pose2;
using kinematic_coverage::core::Ring;
using kinematic_coverage::fuzz::fuzzCheck;

constexpr double kBoxLow = -5.0;
constexpr double kBoxHigh = 35.0;
/// Coordinates snap to this grid (m) when the input asks for it, to provoke collinear
/// and touching vertices.
constexpr double kSnapGrid = 0.5;
/// Polygon size caps. They keep decompositions to about a dozen cells, where the planner's
/// generalized TSP takes milliseconds under the sanitizers (at 20 cells it takes about
/// 0.4 s, which would cap the fuzzer at a few executions a second).
constexpr int kMaxHullVertices = 12;
constexpr int kMaxHoles = 2;
constexpr int kMaxHoleVertices = 6;
/// A leg may touch the offset free area's boundary within this distance (m), as in
/// test/planner/plan_properties.h.
constexpr double kInsideTolerance = 1e-6;
/// A yaw may differ from its leg's heading by this much (rad).
constexpr double kYawTolerance = 1e-9;

/// A coordinate in [low, high], snapped to kSnapGrid when `snap`.
double coordinate(FuzzedDataProvider& input, double low, double high, bool snap) {
  const double value = input.ConsumeFloatingPointInRange(low, high);
  return snap ? std::round(value / kSnapGrid) * kSnapGrid : value;
}

/// A ring of `vertices` vertices: star-shaped about `centre` (angles increasing, so
/// simple unless snapping collapses vertices) or, when `raw`, arbitrary points.
Ring ring(FuzzedDataProvider& input, int vertices, const Point2& centre, double max_radius,
          bool raw, bool snap) {
  Ring result;
  const double step = 2.0 * M_PI / vertices;
  for (int i = 0; i < vertices; ++i) {
    if (raw) {
      result.emplace_back(coordinate(input, kBoxLow, kBoxHigh, snap),
                          coordinate(input, kBoxLow, kBoxHigh, snap));
      continue;
    }
    const double angle = step * (i + input.ConsumeFloatingPointInRange(0.0, 0.5));
    const double radius = input.ConsumeFloatingPointInRange(0.1 * max_radius, max_radius);
    Point2 p = centre + radius * Point2(std::cos(angle), std::sin(angle));
    if (snap) p = (p / kSnapGrid).array().round().matrix() * kSnapGrid;
    result.push_back(p);
  }
  return result;
}

/// A value that checkParameters must reject for most parameters.
double outOfRange(FuzzedDataProvider& input) {
  const double values[] = {
      0.0,  -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
      M_PI, 1.0};
  return values[input.ConsumeIntegralInRange<int>(0, 5)];
}

PlannerParameters parameters(FuzzedDataProvider& input) {
  PlannerParameters p;
  p.decomposition_type = input.ConsumeBool() ? "boustrophedon" : "trapezoidal";
  const char* const costs[] = {"distance", "time", "waypoints"};
  p.cost_function = costs[input.ConsumeIntegralInRange<int>(0, 2)];
  p.sensor_model = input.ConsumeBool() ? "frustum" : "line";
  p.wall_distance = input.ConsumeFloatingPointInRange(0.0, 3.0);
  p.lateral_footprint = input.ConsumeFloatingPointInRange(1.0, 12.0);
  p.sensor_distance = input.ConsumeFloatingPointInRange(0.3, 6.0);
  p.lateral_fov = input.ConsumeFloatingPointInRange(0.5, 3.0);
  p.onward_fov = input.ConsumeFloatingPointInRange(0.1, 3.0);
  p.lateral_overlap = input.ConsumeFloatingPointInRange(0.0, 0.9);
  p.turning_radius = input.ConsumeFloatingPointInRange(0.1, 5.0);
  p.v_max = input.ConsumeFloatingPointInRange(0.1, 3.0);
  p.a_max = input.ConsumeFloatingPointInRange(0.05, 2.0);
  p.yaw_rate_max = input.ConsumeFloatingPointInRange(0.1, 2.0);
  // One parameter in sixteen inputs deliberately out of range.
  if (input.ConsumeIntegralInRange<int>(0, 15) == 0) {
    double* const numbers[] = {
        &p.wall_distance,   &p.lateral_footprint, &p.sensor_distance, &p.lateral_fov, &p.onward_fov,
        &p.lateral_overlap, &p.turning_radius,    &p.v_max,           &p.a_max};
    *numbers[input.ConsumeIntegralInRange<int>(0, 8)] = outOfRange(input);
  }
  return p;
}

Mission mission(FuzzedDataProvider& input) {
  Mission m;
  m.parameters = parameters(input);
  const bool snap = input.ConsumeBool();
  const bool raw = input.ConsumeIntegralInRange<int>(0, 7) == 0;
  const Point2 middle(15.0, 15.0);
  m.polygon.hull =
      ring(input, input.ConsumeIntegralInRange<int>(3, kMaxHullVertices), middle, 20.0, raw, snap);
  const int holes = input.ConsumeIntegralInRange<int>(0, kMaxHoles);
  for (int i = 0; i < holes; ++i) {
    const Point2 centre(coordinate(input, 0.0, 30.0, snap), coordinate(input, 0.0, 30.0, snap));
    const double radius = input.ConsumeFloatingPointInRange(0.5, 6.0);
    m.polygon.holes.push_back(ring(input, input.ConsumeIntegralInRange<int>(3, kMaxHoleVertices),
                                   centre, radius, raw, snap));
  }
  m.start = Point2(coordinate(input, kBoxLow, kBoxHigh, snap),
                   coordinate(input, kBoxLow, kBoxHigh, snap));
  m.goal = Point2(coordinate(input, kBoxLow, kBoxHigh, snap),
                  coordinate(input, kBoxLow, kBoxHigh, snap));
  // Read last, so that the committed corpus decodes as before (an input that ends earlier
  // plans without the repair).
  m.parameters.coverage_repair = input.ConsumeBool();
  // Later still: an input that ends before it decomposes the exact boundary.
  m.parameters.boundary_simplification = input.ConsumeFloatingPointInRange(0.0, 0.5);
  return m;
}

/// A number as YAML: round-trip digits, or what YAML reads as NaN or infinity.
std::string yamlNumber(double value) {
  if (std::isnan(value)) return ".nan";
  if (std::isinf(value)) return value > 0 ? ".inf" : "-.inf";
  return kinematic_coverage::core::formatRoundTrip(value);
}

/// The mission as a mission file for `coverage_tool plan`, written to the file that
/// KC_FUZZ_PRINT_MISSION names, so that a finding replays outside the fuzzer:
///   KC_FUZZ_PRINT_MISSION=mission.yaml planner_fuzzer FINDING
void printMission(const Mission& m, const char* path) {
  const auto ring = [](const Ring& points) {
    std::string text = "[";
    for (std::size_t i = 0; i < points.size(); ++i) {
      text +=
          (i ? ", [" : "[") + yamlNumber(points[i].x()) + ", " + yamlNumber(points[i].y()) + "]";
    }
    return text + "]";
  };
  const PlannerParameters& p = m.parameters;
  std::string text = "polygon:\n  hull: " + ring(m.polygon.hull) + "\n  holes:";
  if (m.polygon.holes.empty()) text += " []";
  for (const Ring& hole : m.polygon.holes) text += "\n    - " + ring(hole);
  text += "\nstart: [" + yamlNumber(m.start.x()) + ", " + yamlNumber(m.start.y()) + "]";
  text += "\ngoal: [" + yamlNumber(m.goal.x()) + ", " + yamlNumber(m.goal.y()) + "]";
  text += "\ndecomposition_type: " + p.decomposition_type;
  text += "\ncost_function: " + p.cost_function;
  text += "\nsensor_model: " + p.sensor_model;
  text += std::string("\ncoverage_repair: ") + (p.coverage_repair ? "true" : "false");
  const std::pair<const char*, double> numbers[] = {
      {"wall_distance", p.wall_distance},
      {"lateral_footprint", p.lateral_footprint},
      {"sensor_distance", p.sensor_distance},
      {"lateral_fov", p.lateral_fov},
      {"onward_fov", p.onward_fov},
      {"lateral_overlap", p.lateral_overlap},
      {"boundary_simplification", p.boundary_simplification},
      {"turning_radius", p.turning_radius},
      {"v_max", p.v_max},
      {"a_max", p.a_max},
      {"yaw_rate_max", p.yaw_rate_max}};
  for (const auto& [name, value] : numbers)
    text += "\n" + std::string(name) + ": " + yamlNumber(value);
  if (std::FILE* file = std::fopen(path, "w")) {
    std::fprintf(file, "%s\n", text.c_str());
    std::fclose(file);
  }
}

void checkPlan(const Mission& m, const PlannedMission& planned) {
  const std::vector<Pose2>& waypoints = planned.plan.waypoints;
  fuzzCheck(!waypoints.empty(), "plan without waypoints");
  for (const Pose2& pose : waypoints) {
    fuzzCheck(std::isfinite(pose.x) && std::isfinite(pose.y) && std::isfinite(pose.yaw),
              "non-finite waypoint");
    fuzzCheck(std::abs(pose.yaw) <= M_PI + 1e-12, "yaw outside [-pi, pi]");
  }
  fuzzCheck((waypoints.front().position() - m.start).norm() <= 1e-9,
            "path does not start at the start");
  fuzzCheck((waypoints.back().position() - m.goal).norm() <= 1e-9, "path does not end at the goal");
  const auto& plan = planned.plan;
  fuzzCheck(plan.first_inside <= plan.last_inside && plan.last_inside < waypoints.size(),
            "inside range outside the waypoints");
  double length = 0.0;
  for (std::size_t i = 0; i + 1 < waypoints.size(); ++i) {
    const Point2 a = waypoints[i].position();
    const Point2 b = waypoints[i + 1].position();
    const std::string leg = "leg " + std::to_string(i);
    fuzzCheck(a != b, leg + " has no length");
    length += (b - a).norm();
    const double heading = std::atan2(b.y() - a.y(), b.x() - a.x());
    fuzzCheck(std::abs(std::remainder(waypoints[i].yaw - heading, 2.0 * M_PI)) <= kYawTolerance,
              "the yaw of waypoint " + std::to_string(i) + " is not its leg's heading");
    // Inside the route area, or out of it toward the exact offset's boundary (the repair's
    // excursions), keeping the wall distance.
    if (i >= plan.first_inside && i + 1 <= plan.last_inside) {
      fuzzCheck(
          kinematic_coverage::core::segmentInside(plan.route_area, a, b, kInsideTolerance) ||
              kinematic_coverage::core::keepsClearance(
                  kinematic_coverage::core::testing::sampledWallDistance(planned.free_area, {a, b}),
                  m.parameters.wall_distance),
          leg + " leaves the route area and comes nearer the walls than the wall distance");
    }
  }
  fuzzCheck(std::isfinite(plan.path_length_m) &&
                std::abs(plan.path_length_m - length) <= 1e-6 * std::max(1.0, length),
            "path_length_m " + std::to_string(plan.path_length_m) + " but the legs add up to " +
                std::to_string(length));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider input(data, size);
  const Mission m = mission(input);
  if (const char* path = std::getenv("KC_FUZZ_PRINT_MISSION")) printMission(m, path);
  kinematic_coverage::fuzz::runExpectingOnlyInvalidInput([&] {
    kinematic_coverage::core::checkParameters(m.parameters);
    const kinematic_coverage::core::PlannedMission planned =
        kinematic_coverage::core::planMission(m);
    checkPlan(m, planned);
  });
  return 0;
}
