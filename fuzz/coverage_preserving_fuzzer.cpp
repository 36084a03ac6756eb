// libFuzzer target: coverage-preserving and coverage-safe smoothing (the global strategy:
// GlobalPathSmoother with a preserved or a safe sensor) on fuzzed waypoint paths, obstacles
// and sensors. Decodes a turning radius, 3 to 5 waypoints, obstacles and the global
// strategy's options as corner_smoothing_fuzzer does (fuzzed_smoothing.h), a footprint of
// any proportions, and for coverage-safe smoothing a wall distance. Every smoothing the
// programme chooses is rasterized (CornerCoverageCheck, up to 512 x 512 cells; the whole
// path for coverage-safe smoothing, PathCoverageCheck), so one execution takes from
// microseconds to about a second: a target of its own, so that corner_smoothing_fuzzer
// keeps its rate. Properties: those of fuzzed_smoothing.h, and kept_for_coverage counts
// only corners left sharp.

#include <fuzzer/FuzzedDataProvider.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "fuzz/fuzz_check.h"
#include "fuzz/fuzzed_smoothing.h"
#include "trajectory_generation_tools/smoothing/global_path_smoother.h"

namespace {

using kinematic_coverage::core::FrustumSensor;
using kinematic_coverage::core::GlobalPathSmoother;
using kinematic_coverage::core::GlobalSmoothingOptions;
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
    const SmoothedPath path = GlobalPathSmoother(area, options).smooth(waypoints);
    kinematic_coverage::fuzz::checkSmoothedPath(area, waypoints, options.min_turning_radius, path);
    const auto& statistics = path.statistics;
    fuzzCheck(
        statistics.kept_for_coverage >= 0 &&
            statistics.kept_for_coverage <= statistics.turns_total - statistics.turns_smoothed,
        "kept_for_coverage counts a smoothed corner");
  });
  return 0;
}
