#include "trajectory_generation_tools/smoothing/smoothed_path_assembler.h"

#include <cmath>

namespace kinematic_coverage::core {
namespace {

/// Joining segments no longer than this (m) are left out; the next primitive then starts
/// within this distance of the previous one's end.
constexpr double kMinSegmentLength = 1e-9;

void count(SmoothingVariant variant, SmoothingStatistics& statistics) {
  ++statistics.turns_smoothed;
  switch (variant) {
    case SmoothingVariant::kReverseCurve:
      ++statistics.reverse_curve;
      break;
    case SmoothingVariant::kBulb:
      ++statistics.bulb;
      break;
    case SmoothingVariant::kInner:
      ++statistics.inner;
      break;
    case SmoothingVariant::kOuterBisector:
      ++statistics.outer_bisector;
      break;
    case SmoothingVariant::kOuterTangent:
      ++statistics.outer_tangent;
      break;
    case SmoothingVariant::kNone:
      break;
  }
}

}  // namespace

SmoothedPath SmoothedPathAssembler::assemble(
    const std::vector<Point2>& corners,
    const std::vector<std::optional<CornerSmoothing>>& smoothings) {
  SmoothedPath path;
  if (corners.size() < 2) return path;
  path.primitives.reserve(2 * corners.size());
  Point2 current = corners.front();  // where the path built so far ends
  for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
    const Point2& b = corners[i];
    const Point2 incoming = (b - corners[i - 1]).normalized();
    ++path.statistics.turns_total;
    const std::optional<CornerSmoothing>& smoothed = smoothings[i - 1];
    if (smoothed) {
      // The joining segment runs along the leg's exact direction, so that its heading
      // matches the first arc's even when it is short.
      const double length = (smoothed->arcs.front().start() - current).dot(incoming);
      if (length > kMinSegmentLength) {
        path.primitives.push_back(PathPrimitive::segment(current, current + length * incoming));
      }
      path.primitives.insert(path.primitives.end(), smoothed->arcs.begin(), smoothed->arcs.end());
      current = smoothed->arcs.back().end();
      count(smoothed->variant, path.statistics);
      if (smoothed->corners == 2 && i + 2 < corners.size()) {
        // A reverse curve or bulb turn also takes the next corner.
        ++i;
        ++path.statistics.turns_total;
        count(smoothed->variant, path.statistics);
      }
      continue;
    }
    const double length = (b - current).dot(incoming);
    if (length > kMinSegmentLength) {
      path.primitives.push_back(PathPrimitive::segment(current, current + length * incoming));
    }
    const Point2 outgoing = (corners[i + 1] - b).normalized();
    const double turn = std::atan2(incoming.x() * outgoing.y() - incoming.y() * outgoing.x(),
                                   incoming.dot(outgoing));
    path.primitives.push_back(
        PathPrimitive::rotation(b, std::atan2(incoming.y(), incoming.x()), turn));
    current = b;
  }
  const Point2 outgoing = (corners.back() - corners[corners.size() - 2]).normalized();
  const double length = (corners.back() - current).dot(outgoing);
  if (length > kMinSegmentLength) {
    path.primitives.push_back(PathPrimitive::segment(current, current + length * outgoing));
  }
  return path;
}

}  // namespace kinematic_coverage::core
