#pragma once

#include <string>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "polygon_coverage_ros_bridge/sweeps/coverage_raster.h"
#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"
#include "trajectory_generation_tools/replanning/remaining_area_options.h"
#include "trajectory_generation_tools/replanning/visited_history.h"

namespace kinematic_coverage::core {

/// A part of the remaining area too small to plan (under replanning_min_area).
struct DroppedPart {
  double area_m2 = 0.0;
  Point2 centroid = Point2::Zero();
};

/// The area still to see after a robot visited some poses, made fit to plan.
struct RemainingArea {
  /// Valid polygons with holes (CCW hulls, CW holes, simple rings, at most
  /// replanning_simplify_tolerance from the exact remaining area's boundary).
  std::vector<PolygonWithHoles> parts;
  double free_area_m2 = 0.0;         ///< the updated free area
  double seen_area_m2 = 0.0;         ///< of it, seen by the visited poses (the method's seen area)
  double remaining_area_m2 = 0.0;    ///< free minus seen, before clean-up
  double kept_area_m2 = 0.0;         ///< the parts' area after clean-up
  std::vector<DroppedPart> dropped;  ///< parts smaller than replanning_min_area, not planned
  double cell_size_m = 0.0;          ///< raster the regions were computed on
};

/// The remaining area of the thesis's section 3.4: the updated free area minus what the
/// visited poses' footprints saw, by `replanning_method`:
/// - `convex_hull`: minus the convex hull of every footprint corner (Fig. 3.9a; it also
///   discards unvisited area inside the hull, as the thesis found);
/// - `concave_hull`: minus the alpha shape of the footprint corners (`alpha`, Fig. 3.9c);
/// - `footprint`: minus the seen area (footprints and the hulls of
///   consecutive pairs, Fig. 3.9b).
/// Made robust as the thesis's conclusions propose: computed on a raster (so every result
/// is a valid polygon, never the non-simple polygons of its Fig. 3.12), slivers narrower
/// than replanning_sliver_fraction of the sweep spacing opened away, parts smaller than
/// replanning_min_area dropped, and boundaries simplified within
/// replanning_simplify_tolerance (at least the raster's cell diagonal, so that its
/// staircases always go) without changing their topology. The raster has sweep spacing /
/// 64 cells.
class RemainingAreaCalculator {
 public:
  /// The calculator of `options` (their ranges checked where they were made:
  /// remainingAreaOptionsOf).
  explicit RemainingAreaCalculator(const RemainingAreaOptions& options);

  /// The remaining area of a cleaned free area after `visited` (oldest first). Throws
  /// InvalidInputError for a non-finite pose.
  RemainingArea compute(const PolygonWithHoles& free_area, const std::vector<Pose2>& visited) const;

  /// The same after a bounded history, whose recorded sensor sees its poses: exactly the
  /// result of its poses while it holds them all, within one of its raster cells after.
  RemainingArea compute(const PolygonWithHoles& free_area, const VisitedHistory& visited) const;

 private:
  /// The raster the remaining area is computed on (sweep spacing / 64 cells, coarser for
  /// maps of more than 4 000 000 of them).
  CoverageRaster rasterCovering(const PolygonWithHoles& free_area) const;
  /// What `sensor` saw along `recent` by `replanning_method`, plus what the history's
  /// folded poses saw when `folded` is given.
  CellMask seenMask(const CoverageRaster& raster, const std::vector<Pose2>& recent,
                    const FrustumSensor& sensor, const VisitedHistory* folded) const;
  /// The remaining area (free minus seen) cleaned of slivers and small parts, simplified.
  RemainingArea fromSeen(const CoverageRaster& raster, const PolygonWithHoles& free_area,
                         const CellMask& seen) const;

  RemainingAreaOptions options_;
};

}  // namespace kinematic_coverage::core
