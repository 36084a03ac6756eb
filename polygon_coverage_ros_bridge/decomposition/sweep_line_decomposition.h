#pragma once

#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// Which cells a sweep-line decomposition keeps.
enum class DecompositionType {
  kBoustrophedon,  ///< cells split only where connectivity changes (Choset's cells)
  kTrapezoidal,    ///< cells split at every vertex (classical trapezoids)
};

/// Where boustrophedon cells end (trapezoidal cells end at every vertex either way).
enum class CellJoining {
  /// A cell ends at every critical point, where the slice's connectivity changes
  /// (Choset's cells, the thesis's).
  kAtCriticalPoints,
  /// Across a critical point one cell goes on into the neighbour it shares the longest
  /// slice with: every cell stays monotone, but a bay or an island no longer cuts the
  /// open water beside it into new cells, whose lanes would not line up.
  kLongestOverlap,
};

/// The joining a decomposition of `type` applies: `joining` for boustrophedon cells;
/// trapezoidal cells end at every vertex whatever `joining` says.
inline CellJoining appliedCellJoining(DecompositionType type, CellJoining joining) {
  return type == DecompositionType::kBoustrophedon ? joining : CellJoining::kAtCriticalPoints;
}

/// Decomposes a polygon with holes into cells that lanes parallel to a given direction
/// sweep without leaving: a vertical line (in the frame where the direction is +y) is
/// swept across the area; the slabs between consecutive vertex positions hold
/// trapezoids, which are joined across slab boundaries where nothing changes
/// (trapezoidal: the same two bounding edges; boustrophedon: a one-to-one connection,
/// i.e. no critical point, or with CellJoining::kLongestOverlap a chosen connection). Every cell is
/// simple, counter-clockwise and monotone with respect to the direction; the cells tile the
/// polygon.
class SweepLineDecomposition {
 public:
  explicit SweepLineDecomposition(DecompositionType type,
                                  CellJoining joining = CellJoining::kAtCriticalPoints)
      : type_(type), joining_(appliedCellJoining(type, joining)) {}

  /// The cells of `polygon` (CCW hull, CW holes) for lanes parallel to `direction`.
  /// Throws InvalidInputError when the boundary crosses itself.
  std::vector<Ring> decompose(const PolygonWithHoles& polygon, double direction) const;

 private:
  DecompositionType type_;
  CellJoining joining_;  ///< as applied to `type_`
};

}  // namespace kinematic_coverage::core
