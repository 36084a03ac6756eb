#pragma once

#include <vector>

#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"
#include "trajectory_generation_tools/smoothing/boundary_edge_index.h"
#include "trajectory_generation_tools/smoothing/corner_smoothing.h"

namespace kinematic_coverage::core {

/// Whether a corner smoothing lets the sensor see what the sharp corner let it see: the
/// test of coverage-preserving smoothing (the thesis's Chapter 5 names the
/// coverage that inner smoothing of acute corners loses as an open problem).
///
/// Both versions of the corner are driven from a footprint's reach before the smoothing
/// to a footprint's reach after it: the sharp one along the legs with an in-place rotation
/// at B, the smoothed one along the legs and the arcs. What the sharp one sees there, in
/// the free area, and the smoothed one does not, is the lost area, measured on a local
/// raster whose cells are a small fraction of the footprint. Other corners and lanes are
/// not counted, so the test is conservative: it may keep a corner sharp whose loss another
/// lane would have made up.
class CornerCoverageCheck {
 public:
  /// Cells of the local raster per footprint length (or width, if shorter; the width for a
  /// line sensor).
  static constexpr double kCellsPerFootprint = 24.0;
  /// A lost area of at most this many cells counts as none: the two versions are
  /// rasterized differently (swept rotation sectors against sampled arcs).
  static constexpr double kToleratedCells = 2.0;

  /// Containment against `index`, which must outlive this object; `sensor` sees.
  CornerCoverageCheck(const BoundaryEdgeIndex& index, const FrustumSensor& sensor);

  /// The lost area (m^2) of `smoothing` of the sharp corners of `corner_path`: a, b, c for
  /// one corner, or a, b1, b2, c for a reverse curve; `smoothing` starts on the first leg
  /// and ends on the last.
  double lostArea(const std::vector<Point2>& corner_path, const CornerSmoothing& smoothing) const;

  /// True when the lost area is at most kToleratedCells cells.
  bool preserves(const std::vector<Point2>& corner_path, const CornerSmoothing& smoothing) const;

 private:
  /// A lost area and the cell area of the raster it was measured on.
  struct Loss {
    double area = 0.0;
    double cell_area = 0.0;
  };
  Loss measure(const std::vector<Point2>& corner_path, const CornerSmoothing& smoothing) const;

  const BoundaryEdgeIndex& index_;
  FrustumSensor sensor_;
  double cell_size_;
};

}  // namespace kinematic_coverage::core
