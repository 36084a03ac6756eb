// libFuzzer target: coverage-preserving and coverage-safe smoothing (the global strategy:
// GlobalPathSmoother with a preserved or a safe sensor) on fuzzed waypoint paths, obstacles
// and sensors. Decodes a turning radius, 3 to 5 waypoints, obstacles and the global
// strategy's options as corner_smoothing_fuzzer does (fuzzed_smoothing.h), a footprint of
// any proportions, and for coverage-safe smoothing a wall distance. Every smoothing the
// programme chooses is rasterized (CornerCoverageCheck, up to 512 x 512 cells; the whole
// path for coverage-safe smoothing, PathCoverageCheck), so one execution takes from
// microseconds to about a second: a target of its own, so that corner_smoothing_fuzzer
// keeps its rate. Properties: those of fuzzed_smoothing.h; kept_for_coverage counts only
// corners left sharp; and what each mode promises (docs/REFERENCE.md, smoothing_strategy):
// with a preserved sensor every smoothing taken preserves what its sharp corners let the
// sensor see (CornerCoverageCheck), and with a safe sensor the whole smoothed path loses
// at most the tolerated share of the reachable area the sharp path sees (PathCoverageCheck,
// the path measured as one stretch, so a loss that the programme split among its corners
// counts whole).

#include <fuzzer/FuzzedDataProvider.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "fuzz/fuzz_check.h"
#include "fuzz/fuzzed_smoothing.h"
#include "trajectory_generation_tools/smoothing/boundary_edge_index.h"
#include "trajectory_generation_tools/smoothing/corner_coverage_check.h"
#include "trajectory_generation_tools/smoothing/global_path_smoother.h"
#include "trajectory_generation_tools/smoothing/path_coverage_check.h"

namespace {

using kinematic_coverage::core::BoundaryEdgeIndex;
using kinematic_coverage::core::CornerCoverageCheck;
using kinematic_coverage::core::FrustumSensor;
using kinematic_coverage::core::GlobalPathSmoother;
using kinematic_coverage::core::GlobalSmoothingOptions;
using kinematic_coverage::core::GlobalSmoothingPlan;
using kinematic_coverage::core::GlobalSmoothingProgramme;
using kinematic_coverage::core::PathCoverageCheck;
using kinematic_coverage::core::Point2;
using kinematic_coverage::core::PolygonWithHoles;
using kinematic_coverage::core::SmoothedPath;
using kinematic_coverage::fuzz::fuzzCheck;

constexpr int kMinWaypoints = 3;
constexpr int kMaxWaypoints = 5;
/// Footprint sides (m): from a hundredth of the smallest turning radius to past the largest.
constexpr double kMinFootprintWidth = 1e-4;
constexpr double kMaxFootprintSide = 40.0;
/// Wall distances (m) of coverage-safe smoothing, which shape its reachable area.
constexpr double kMaxWallDistance = 5.0;

/// Coverage-preserving smoothing's promise: every corner smoothing the plan takes keeps what
/// the sharp corners it replaces let the sensor see, in the free area.
void checkPreserved(const PolygonWithHoles& area, const GlobalSmoothingOptions& options,
                    const GlobalSmoothingProgramme& programme, const GlobalSmoothingPlan& plan) {
  const BoundaryEdgeIndex index(area, options.clearance);
  const CornerCoverageCheck check(index, *options.preserved_sensor);
  for (std::size_t i = 0; i < plan.choice.size(); ++i) {
    if (plan.choice[i] == GlobalSmoothingProgramme::kNoCandidate) continue;
    const auto& candidate = programme.candidates()[i][static_cast<std::size_t>(plan.choice[i])];
    if (!candidate.smoothing) continue;
    fuzzCheck(check.preserves(candidate.corner_path, *candidate.smoothing),
              "coverage-preserving smoothing took a corner smoothing that loses area");
  }
}

/// Coverage-safe smoothing's promise: the smoothed path loses at most the tolerated share
/// of the reachable area that the sharp path sees.
void checkSafe(const PolygonWithHoles& area, const GlobalSmoothingOptions& options,
               const GlobalSmoothingPlan& plan, const SmoothedPath& path) {
  PathCoverageCheck check(area, options.wall_distance, options.exact_offset_parts,
                          *options.safe_sensor, plan.waypoints, options.coverage_safe_area);
  const std::size_t lost = check.lostCells(path.primitives, {plan.waypoints}).front();
  fuzzCheck(lost <= check.toleratedLostCells(),
            "coverage-safe smoothing loses more of the reachable area than it tolerates");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider input(data, size);
  const double radius = input.ConsumeFloatingPointInRange(0.01, 20.0);
  const bool snap = input.ConsumeBool();
  std::vector<Point2> waypoints;
  const int count = input.ConsumeIntegralInRange<int>(kMinWaypoints, kMaxWaypoints);
  for (int i = 0; i < count; ++i) waypoints.push_back(kinematic_coverage::fuzz::point(input, snap));
  const PolygonWithHoles area = kinematic_coverage::fuzz::obstacles(input);
  GlobalSmoothingOptions options = kinematic_coverage::fuzz::globalOptions(input, radius);
  const FrustumSensor sensor(
      input.ConsumeFloatingPointInRange(kMinFootprintWidth, kMaxFootprintSide),
      input.ConsumeFloatingPointInRange(0.0, kMaxFootprintSide),
      input.ConsumeFloatingPointInRange(0.0, 0.9));
  if (input.ConsumeBool()) {
    options.makeCoverageSafe(sensor, input.ConsumeFloatingPointInRange(0.0, kMaxWallDistance));
  } else {
    options.preserved_sensor = sensor;
  }

  kinematic_coverage::fuzz::runExpectingOnlyInvalidInput([&] {
    const GlobalPathSmoother smoother(area, options);
    const SmoothedPath path = smoother.smooth(waypoints);
    kinematic_coverage::fuzz::checkSmoothedPath(area, waypoints, options.min_turning_radius, path);
    const GlobalSmoothingProgramme programme = smoother.programme(waypoints);
    const GlobalSmoothingPlan plan = programme.plan();
    if (options.preserved_sensor) {
      checkPreserved(area, options, programme, plan);
    } else if (plan.waypoints.size() >= 2) {
      checkSafe(area, options, plan, path);
    }
    const auto& statistics = path.statistics;
    fuzzCheck(
        statistics.kept_for_coverage >= 0 &&
            statistics.kept_for_coverage <= statistics.turns_total - statistics.turns_smoothed,
        "kept_for_coverage counts a smoothed corner");
  });
  return 0;
}
