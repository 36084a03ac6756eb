#pragma once

#include <optional>
#include <vector>

#include "trajectory_generation_tools/path/path_primitive.h"

namespace kinematic_coverage::core {

/// A turn of continuous curvature that replaces a circular arc between two straight legs.
struct ContinuousCurvatureTurnShape {
  /// A clothoid from curvature 0, an arc (none when the turn is too small for one) and a
  /// clothoid back to curvature 0, each starting where the one before ends.
  std::vector<PathPrimitive> primitives;
  /// m: how far each end lies beyond the arc's end, back along the incoming leg and on
  /// along the outgoing one (the legs lose this much each).
  double extension = 0.0;
};

/// The symmetric clothoid-arc-clothoid turn (the "CC turn" of Fraichard and Scheuer, 2004)
/// tangent to the two legs an arc joins, for a vehicle whose curvature may change by at
/// most a given rate per metre (`curvature_rate_max`). Its curvature never exceeds the
/// arc's: the clothoids rise to 1 / radius where the turn is large enough, and to
/// sqrt(turn * rate) (a turn of two clothoids) where it is not. The turn then starts and ends
/// farther from the legs' crossing than the arc, and bends deeper into the corner.
class ContinuousCurvatureTurn {
 public:
  /// Turns (rad) outside (kMinTurn, pi - kMinTurn) have no such turn here.
  static constexpr double kMinTurn = 1e-6;

  /// The turn replacing `arc` (an arc primitive) for a curvature rate of `curvature_rate`
  /// (1/m^2, > 0); none for another kind, a turn outside (kMinTurn, pi - kMinTurn) or a
  /// non-finite result.
  static std::optional<ContinuousCurvatureTurnShape> replacing(const PathPrimitive& arc,
                                                               double curvature_rate);
};

}  // namespace kinematic_coverage::core
