#pragma once

#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// Which cells a sweep-line decomposition keeps.
enum class DecompositionType {
  kBoustrophedon,  ///< cells split only where connectivity changes (Choset's cells)
  kTrapezoidal,    ///< cells split at every vertex (classical trapezoids)
};

/// Decomposes a polygon with holes into cells that lanes parallel to a given direction
/// sweep without leaving: a vertical line (in the frame where the direction is +y) is
/// swept across the area; the slabs between consecutive vertex positions hold
/// trapezoids, which are joined across slab boundaries where nothing changes
/// (trapezoidal: the same two bounding edges; boustrophedon: a one-to-one connection,
/// i.e. no critical point). Every cell is simple, counter-clockwise and monotone with
/// respect to the direction; the cells tile the polygon.
class SweepLineDecomposition {
 public:
  explicit SweepLineDecomposition(DecompositionType type) : type_(type) {}

  /// The cells of `polygon` (CCW hull, CW holes) for lanes parallel to `direction`.
  /// Throws InvalidInputError when the boundary crosses itself.
  std::vector<Ring> decompose(const PolygonWithHoles& polygon, double direction) const;

 private:
  DecompositionType type_;
};

}  // namespace kinematic_coverage::core
