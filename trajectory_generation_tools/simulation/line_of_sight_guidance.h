#pragma once

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// Lookahead-based line-of-sight guidance on a straight path piece (Fossen, Handbook of
/// Marine Craft Hydrodynamics and Motion Control, 2nd ed. 2021, Sec. 12.4): the desired
/// course chi_d = pi_p - atan(y_e / Delta), with pi_p the piece's direction, y_e the
/// cross-track error and Delta the look-ahead distance. A vehicle that holds that course at
/// a speed U closes its cross-track error as y_e' = -U y_e / sqrt(Delta^2 + y_e^2):
/// monotonically, without overshoot.
class LineOfSightGuidance {
 public:
  /// Throws InvalidInputError for a look-ahead that is not finite and > 0 (m).
  explicit LineOfSightGuidance(double lookahead);

  /// m: the signed distance of `position` from the line through `from` and `to`, positive
  /// to its left. 0 for a piece shorter than kShortestPiece.
  static double crossTrackError(const Point2& from, const Point2& to, const Point2& position);

  /// rad in (-pi, pi]: the desired course over ground at `position` for the piece from
  /// `from` to `to`; for a piece shorter than kShortestPiece, the bearing to `to`.
  double course(const Point2& from, const Point2& to, const Point2& position) const;

  double lookahead() const { return lookahead_; }

  /// m: pieces shorter than this have no direction.
  static constexpr double kShortestPiece = 1e-9;

 private:
  double lookahead_;
};

}  // namespace kinematic_coverage::core
