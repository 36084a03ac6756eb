#include "trajectory_generation_tools/trajectory/continuous_curvature_turns.h"

#include <cmath>
#include <string>

#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "trajectory_generation_tools/trajectory/continuous_curvature_turn.h"
#include "trajectory_generation_tools/trajectory/primitive_distance.h"
#include "trajectory_generation_tools/trajectory/primitive_path_metrics.h"

namespace kinematic_coverage::core {
namespace {

/// rad: legs and arcs whose headings meet within this are joined smoothly.
constexpr double kJoinHeadingTolerance = 1e-6;
/// m: a shortened leg shorter than this is dropped.
constexpr double kDroppedLegLength = 1e-9;
/// m: slack of the clearance comparison: a clothoid's clearance is a lower bound within
/// kClothoidDistanceTolerance, and a turn that ends on its legs is exactly as near an
/// obstacle there as they are.
constexpr double kClearanceSlack = 2.0 * kClothoidDistanceTolerance;

bool joinsSmoothly(const PathPrimitive& before, const PathPrimitive& after) {
  return std::abs(wrapAngle(after.startPose().yaw - before.endPose().yaw)) <= kJoinHeadingTolerance;
}

}  // namespace

struct ContinuousCurvatureTurns::Candidate {
  std::size_t arc = 0;  ///< index of the arc in the path
  ContinuousCurvatureTurnShape shape;
  ReplacedStretch stretch;  ///< from the turn's start, by the legs' crossing, to its end
};

ContinuousCurvatureTurns::ContinuousCurvatureTurns(const PolygonWithHoles& free_area,
                                                   double curvature_rate_max)
    : free_area_(free_area), curvature_rate_max_(curvature_rate_max) {
  if (!std::isfinite(curvature_rate_max) || !(curvature_rate_max > 0.0)) {
    throw InvalidInputError("the curvature rate limit must be a finite number > 0 (1/m^2), got " +
                            formatNumber(curvature_rate_max));
  }
}

std::vector<ContinuousCurvatureTurns::Candidate> ContinuousCurvatureTurns::candidates(
    const std::vector<PathPrimitive>& path, ContinuousCurvaturePath& result) const {
  std::vector<Candidate> found;
  // Leg length already given to the turn at a leg's start (its end's turn comes later).
  std::vector<double> taken_at_start(path.size(), 0.0);
  for (std::size_t i = 1; i + 1 < path.size(); ++i) {
    const PathPrimitive& before = path[i - 1];
    const PathPrimitive& arc = path[i];
    const PathPrimitive& after = path[i + 1];
    if (arc.kind() != PrimitiveKind::kArc || before.kind() != PrimitiveKind::kSegment ||
        after.kind() != PrimitiveKind::kSegment || !joinsSmoothly(before, arc) ||
        !joinsSmoothly(arc, after)) {
      continue;
    }
    std::optional<ContinuousCurvatureTurnShape> shape =
        ContinuousCurvatureTurn::replacing(arc, curvature_rate_max_);
    if (!shape) continue;
    const double extension = shape->extension;
    if (before.length() - taken_at_start[i - 1] < extension || after.length() < extension) {
      ++result.kept_for_room;
      continue;
    }
    // What the turn replaces: the legs' last and first `extension` metres and the arc.
    const Point2 in = before.end() - before.start();
    const Point2 out = after.end() - after.start();
    const std::vector<PathPrimitive> replaced{
        PathPrimitive::segment(before.end() - extension * in.normalized(), before.end()), arc,
        PathPrimitive::segment(after.start(), after.start() + extension * out.normalized())};
    if (primitivePathClearance(shape->primitives, free_area_) + kClearanceSlack <
        primitivePathClearance(replaced, free_area_)) {
      ++result.kept_for_clearance;
      continue;
    }
    taken_at_start[i + 1] = extension;
    const Point2 crossing =
        arc.start() + arc.radius() * std::tan(0.5 * std::abs(arc.sweep())) * in.normalized();
    Candidate candidate{i, std::move(*shape), {}};
    candidate.stretch = {candidate.shape.primitives.front().start(), crossing,
                         candidate.shape.primitives.back().end()};
    found.push_back(std::move(candidate));
  }
  return found;
}

std::vector<PathPrimitive> ContinuousCurvatureTurns::assembled(
    const std::vector<PathPrimitive>& path, const std::vector<Candidate>& candidates,
    const std::vector<bool>& accepted) {
  std::vector<PathPrimitive> primitives = path;
  // From the last turn back, so that the indices of the earlier ones stay valid.
  for (std::size_t c = candidates.size(); c-- > 0;) {
    if (!accepted[c]) continue;
    const Candidate& candidate = candidates[c];
    const std::size_t i = candidate.arc;
    PathPrimitive& before = primitives[i - 1];
    PathPrimitive& after = primitives[i + 1];
    before = PathPrimitive::segment(before.start(), candidate.stretch.front())
                 .withVariant(before.variant());
    after =
        PathPrimitive::segment(candidate.stretch.back(), after.end()).withVariant(after.variant());
    primitives.erase(primitives.begin() + static_cast<std::ptrdiff_t>(i));
    primitives.insert(primitives.begin() + static_cast<std::ptrdiff_t>(i),
                      candidate.shape.primitives.begin(), candidate.shape.primitives.end());
  }
  std::vector<PathPrimitive> kept;
  kept.reserve(primitives.size());
  for (const PathPrimitive& primitive : primitives) {
    const bool emptied_leg = primitive.kind() == PrimitiveKind::kSegment &&
                             primitive.length() < kDroppedLegLength && primitives.size() > 1;
    if (!emptied_leg) kept.push_back(primitive);
  }
  return kept;
}

void ContinuousCurvatureTurns::keepCoverage(const std::vector<PathPrimitive>& path,
                                            const std::vector<Candidate>& candidates,
                                            std::vector<bool>& accepted,
                                            PathCoverageCheck& coverage,
                                            ContinuousCurvaturePath& result) const {
  // Every round refuses a turn or ends, so the rounds end.
  for (;;) {
    std::vector<ReplacedStretch> stretches;
    std::vector<std::size_t> turn_of;
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      if (!accepted[c]) continue;
      stretches.push_back(candidates[c].stretch);
      turn_of.push_back(c);
    }
    if (stretches.empty()) return;
    const std::vector<std::size_t> lost_with_arcs = coverage.lostCells(path, stretches);
    const std::vector<std::size_t> lost_with_turns =
        coverage.lostCells(assembled(path, candidates, accepted), stretches);
    bool refused = false;
    for (std::size_t s = 0; s < stretches.size(); ++s) {
      if (lost_with_turns[s] > lost_with_arcs[s]) {
        accepted[turn_of[s]] = false;
        ++result.kept_for_coverage;
        refused = true;
      }
    }
    if (!refused) return;
  }
}

ContinuousCurvaturePath ContinuousCurvatureTurns::apply(const std::vector<PathPrimitive>& path,
                                                        PathCoverageCheck* coverage) const {
  ContinuousCurvaturePath result;
  const std::vector<Candidate> found = candidates(path, result);
  std::vector<bool> accepted(found.size(), true);
  if (coverage != nullptr) keepCoverage(path, found, accepted, *coverage, result);
  result.primitives = assembled(path, found, accepted);
  for (const bool turn : accepted) result.turns_clothoid += turn ? 1 : 0;
  return result;
}

}  // namespace kinematic_coverage::core
