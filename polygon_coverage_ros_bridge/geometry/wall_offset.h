#pragma once

#include <memory>
#include <string>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// Most vertex pairs (vertices x reflex vertices, counted on each ring taken counter-
/// clockwise) of one ring whose straight skeleton the wall offset computes: CGAL's skeleton
/// builder keeps event-time caches for every such pair, about 50 bytes each on a hull
/// (measured: a 2 000-vertex noisy shoreline with 974 reflex vertices takes 104 MB, 4 000
/// with 1 966 take 396 MB), so the limit keeps one offset under about 400 MB.
constexpr double kMaxSkeletonPairs = 8e6;

/// The vertex pairs of the ring's straight skeleton (its vertices times its reflex vertices,
/// the ring taken counter-clockwise), which kMaxSkeletonPairs bounds.
double skeletonPairs(const Ring& ring);

/// True when the straight skeleton of every ring of the area is within kMaxSkeletonPairs.
bool fitsSkeletonLimit(const PolygonWithHoles& area);

/// The offset free area (docs/REFERENCE.md, Geometry and input rules): one part, or
/// several where the offset splits the free area (a strait narrower than two wall
/// distances).
struct OffsetFreeArea {
  std::vector<PolygonWithHoles> parts;  ///< CCW hulls, CW holes; largest first
};

/// Computes the points of a cleaned free area at least `wall_distance` from the hull and
/// from every hole, with mitred (straight-skeleton) offsets: the hull shrinks by its
/// interior skeleton, each hole grows by its exterior skeleton, and the grown holes are
/// subtracted from the shrunk hull with exact Boolean operations, so that holes growing
/// into each other or into the hull merge. Every part of the result is returned, the
/// largest first. Throws InvalidInputError when nothing is left, and, before any skeleton is built,
/// when a ring has more than kMaxSkeletonPairs vertex pairs.
OffsetFreeArea computeOffsetFreeArea(const PolygonWithHoles& free_area, double wall_distance);

/// computeOffsetFreeArea of one free area at any distance up to a largest one, with the
/// straight skeletons built once: OffsetPartJoiner offsets the same area at a dozen
/// distances, and building the skeletons is a third or more of each offset. The area must
/// outlive this object.
class WallOffset {
 public:
  /// Builds the skeletons up to `max_distance` > 0. Throws as computeOffsetFreeArea does
  /// before any skeleton is built.
  WallOffset(const PolygonWithHoles& free_area, double max_distance);
  ~WallOffset();
  WallOffset(const WallOffset&) = delete;
  WallOffset& operator=(const WallOffset&) = delete;

  /// computeOffsetFreeArea(free_area, distance), 0 < distance <= max_distance.
  OffsetFreeArea at(double distance) const;

 private:
  struct Skeletons;
  std::unique_ptr<Skeletons> skeletons_;
};

}  // namespace kinematic_coverage::core
