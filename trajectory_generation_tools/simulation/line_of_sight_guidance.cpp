#include "trajectory_generation_tools/simulation/line_of_sight_guidance.h"

#include <cmath>

#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {

LineOfSightGuidance::LineOfSightGuidance(double lookahead) : lookahead_(lookahead) {
  if (!(std::isfinite(lookahead_) && lookahead_ > 0.0)) {
    throw InvalidInputError(
        "line-of-sight guidance: the look-ahead must be finite and > 0 m, got " +
        formatNumber(lookahead_));
  }
}

double LineOfSightGuidance::crossTrackError(const Point2& from, const Point2& to,
                                            const Point2& position) {
  const Point2 along = to - from;
  const double length = along.norm();
  if (length < kShortestPiece) return 0.0;
  const Point2 offset = position - from;
  return (along.x() * offset.y() - along.y() * offset.x()) / length;
}

double LineOfSightGuidance::course(const Point2& from, const Point2& to,
                                   const Point2& position) const {
  const Point2 along = to - from;
  if (along.norm() < kShortestPiece) {
    const Point2 bearing = to - position;
    return std::atan2(bearing.y(), bearing.x());
  }
  const double piece_direction = std::atan2(along.y(), along.x());
  return wrapAngle(piece_direction - std::atan(crossTrackError(from, to, position) / lookahead_));
}

}  // namespace kinematic_coverage::core
