// libFuzzer target: corner smoothing (Algorithm 1, thesis 3.2) on fuzzed corners and
// obstacles. Decodes A, B, C, the turning radius, an optional hull and up to four small
// star-shaped holes (disjoint and inside the hull, so that "inside the free area" has one
// meaning), and extra waypoints; runs CornerSmoother on the corner, and smooths the
// waypoints A, B, C, ... with Algorithm 1 (PathSmoother) and with the global smoothing
// strategy (GlobalPathSmoother, with a fuzzed min_turning_radius and velocity model;
// coverage_preserving_fuzzer covers its coverage-preserving option). Properties: those of
// fuzzed_smoothing.h for both paths, and of a feasible corner smoothing:
// - the arcs leave [A, B] and join [B, C] tangentially, and meet one another tangentially;
// - curvature at most 1 / radius;
// - arcs and the corner's joining segments off every hull and hole edge and inside the
//   free area.

#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fuzz/fuzz_check.h"
#include "fuzz/fuzzed_smoothing.h"
#include "trajectory_generation_tools/smoothing/boundary_edge_index.h"
#include "trajectory_generation_tools/smoothing/corner_smoother.h"
#include "trajectory_generation_tools/smoothing/global_path_smoother.h"

namespace {

using kinematic_coverage::core::BoundaryEdgeIndex;
using kinematic_coverage::core::Corner;
using kinematic_coverage::core::CornerSmoother;
using kinematic_coverage::core::CornerSmoothing;
using kinematic_coverage::core::GlobalPathSmoother;
using kinematic_coverage::core::GlobalSmoothingOptions;
using kinematic_coverage::core::kJoinHeadingTolerance;
using kinematic_coverage::core::kJoinPositionTolerance;
using kinematic_coverage::core::PathPrimitive;
using kinematic_coverage::core::PathSmoother;
using kinematic_coverage::core::Point2;
using kinematic_coverage::core::PolygonWithHoles;
using kinematic_coverage::core::PrimitiveKind;
using kinematic_coverage::core::SmoothingVariant;
using kinematic_coverage::fuzz::checkClear;
using kinematic_coverage::fuzz::checkSmoothedPath;
using kinematic_coverage::fuzz::fuzzCheck;
using kinematic_coverage::fuzz::headingGap;
using kinematic_coverage::fuzz::kCurvatureSlack;

/// The properties of a feasible smoothing of `corner`.
void checkCornerSmoothing(const PolygonWithHoles& area, const Corner& corner,
                          const CornerSmoothing& smoothing, const CornerSmoother& smoother) {
  fuzzCheck(smoother.feasible(corner, smoothing), "smooth() returned an infeasible smoothing");
  fuzzCheck(!smoothing.arcs.empty(), "smoothing without arcs");
  fuzzCheck(smoothing.variant != SmoothingVariant::kNone, "smoothing without a variant");
  const double heading_in = corner.incoming.isZero()
                                ? kinematic_coverage::core::headingOf(corner.a, corner.b)
                                : std::atan2(corner.incoming.y(), corner.incoming.x());
  const double heading_out = kinematic_coverage::core::headingOf(corner.b, corner.c);
  const PathPrimitive& first = smoothing.arcs.front();
  const PathPrimitive& last = smoothing.arcs.back();
  fuzzCheck(kinematic_coverage::core::distanceToSegment(first.start(), corner.a, corner.b) <=
                kJoinPositionTolerance,
            "first arc does not start on [A, B]");
  fuzzCheck(headingGap(first.startPose().yaw, heading_in) <= kJoinHeadingTolerance,
            "first arc does not leave [A, B] tangentially");
  fuzzCheck(kinematic_coverage::core::distanceToSegment(last.end(), corner.b, corner.c) <=
                kJoinPositionTolerance,
            "last arc does not end on [B, C]");
  fuzzCheck(headingGap(last.endPose().yaw, heading_out) <= kJoinHeadingTolerance,
            "last arc does not join [B, C] tangentially");
  for (std::size_t i = 0; i < smoothing.arcs.size(); ++i) {
    const PathPrimitive& arc = smoothing.arcs[i];
    fuzzCheck(arc.kind() == PrimitiveKind::kArc, "smoothing primitive is not an arc");
    fuzzCheck(arc.variant() == smoothing.variant, "arc tagged with another variant");
    fuzzCheck(arc.curvature() <= (1.0 + kCurvatureSlack) / corner.radius,
              "arc curvature " + std::to_string(arc.curvature()) + " above 1 / radius");
    checkClear(area, arc, "arc " + std::to_string(i));
    if (i == 0) continue;
    const PathPrimitive& previous = smoothing.arcs[i - 1];
    fuzzCheck((previous.end() - arc.start()).norm() <= kJoinPositionTolerance,
              "arcs " + std::to_string(i - 1) + " and " + std::to_string(i) + " do not meet");
    fuzzCheck(headingGap(previous.endPose().yaw, arc.startPose().yaw) <= kJoinHeadingTolerance,
              "arcs " + std::to_string(i - 1) + " and " + std::to_string(i) + " are not tangent");
  }
  if ((first.start() - corner.a).norm() > kJoinPositionTolerance) {
    checkClear(area, PathPrimitive::segment(corner.a, first.start()), "segment [A, I1]");
  }
  if ((corner.c - last.end()).norm() > kJoinPositionTolerance) {
    checkClear(area, PathPrimitive::segment(last.end(), corner.c), "segment [I_last, C]");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider input(data, size);
  const double radius = input.ConsumeFloatingPointInRange(0.01, 20.0);
  const bool snap = input.ConsumeBool();
  Corner corner;
  corner.radius = radius;
  corner.a = kinematic_coverage::fuzz::point(input, snap);
  corner.b = kinematic_coverage::fuzz::point(input, snap);
  corner.c = kinematic_coverage::fuzz::point(input, snap);
  if (input.ConsumeIntegralInRange<int>(0, 7) == 0) {
    // The previous smoothing ended exactly at B: the direction comes from `incoming`.
    const double angle = input.ConsumeFloatingPointInRange(-M_PI, M_PI);
    corner.a = corner.b;
    corner.incoming = Point2(std::cos(angle), std::sin(angle));
  }
  const PolygonWithHoles area = kinematic_coverage::fuzz::obstacles(input);
  std::vector<Point2> waypoints{corner.a, corner.b, corner.c};
  const int extra = input.ConsumeIntegralInRange<int>(0, 3);
  for (int i = 0; i < extra; ++i) waypoints.push_back(kinematic_coverage::fuzz::point(input, snap));
  const GlobalSmoothingOptions global_options =
      kinematic_coverage::fuzz::globalOptions(input, radius);

  kinematic_coverage::fuzz::runExpectingOnlyInvalidInput([&] {
    const BoundaryEdgeIndex index(area);
    const CornerSmoother smoother(index);
    const std::optional<CornerSmoothing> smoothing = smoother.smooth(corner);
    if (smoothing) checkCornerSmoothing(area, corner, *smoothing, smoother);
    const PathSmoother path_smoother(area, radius);
    checkSmoothedPath(area, waypoints, radius, path_smoother.smooth(waypoints));
    const GlobalPathSmoother global_smoother(area, global_options);
    checkSmoothedPath(area, waypoints, global_options.min_turning_radius,
                      global_smoother.smooth(waypoints));
  });
  return 0;
}
