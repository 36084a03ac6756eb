#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "polygon_coverage_ros_bridge/sweeps/coverage_raster.h"
#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"
#include "polygon_coverage_ros_bridge/sweeps/waypoint_path_poses.h"

namespace kinematic_coverage::core {

/// The heatmap as a grid, for plots: `visits[index]` is how many
/// separate times the sensor saw the cell, saturating at 65535 (row-major from `origin`,
/// the grid's minimum corner, with square cells of `cell_size`).
struct Heatmap {
  Point2 origin = Point2::Zero();
  double cell_size = 0.0;
  int columns = 0;
  int rows = 0;
  std::vector<std::uint16_t> visits;
};

/// Pieces into which to cut an arc of `sweep` radians whose footprints reach at most
/// `farthest` metres from its centre, so that the hull of each two consecutive footprints
/// (SeenArea's step) misses at most half a `cell_size` of what the arc sweeps (the sagitta
/// farthest * dtheta^2 / 8 of a step of dtheta = 2 sqrt(cell_size / farthest)), with steps
/// of at most `max_step` radians. At least 1.
int sweptArcPieces(double sweep, double farthest, double cell_size, double max_step);

/// The seen area (docs/REFERENCE.md, Sensor footprint and coverage) on a CoverageRaster
/// (the thesis's coverage and heatmaps, Fig. 4.2 and 4.6): the union of the
/// footprints at the poses and, for each two consecutive poses at different positions
/// (farther apart than kSamePositionTolerance), the convex hull of their footprints. Each pair of
/// consecutive poses is one step; a cell seen in consecutive steps is one visit, so the heatmap
/// does not depend on how densely a trajectory is sampled.
class SeenArea {
 public:
  /// Nothing seen yet on `raster`.
  explicit SeenArea(const CoverageRaster& raster);

  /// Adds what `sensor` sees along `poses` (one pose: its footprint). Separate calls are
  /// separate passes: a cell seen at the end of one and the start of the next counts twice.
  /// Throws InvalidInputError for a non-finite pose (nothing is added then).
  void addTrajectory(const std::vector<Pose2>& poses, const FrustumSensor& sensor);

  /// Adds what `sensor` sees along a waypoint path driven as straight legs with in-place
  /// rotations between them (waypointPathPoses): each leg sweeps the convex hull of its end
  /// footprints, and each rotation step of at most `rotation_step` sweeps its two
  /// footprints and the circular sectors that the footprint's corners sweep about the
  /// centre, which is exactly the area a rotating convex footprint passes over (up to the
  /// chords of arcs a few hundredths of a radian long). One pass, as addTrajectory.
  /// Throws InvalidInputError as waypointPathPoses does (nothing is added then).
  void addWaypointPath(const std::vector<Pose2>& waypoints, const FrustumSensor& sensor,
                       double rotation_step = kDefaultRotationStep);

  /// Adds what `sensor` sees along `poses` as addTrajectory does, except that consecutive
  /// poses at the same position are an in-place rotation between their headings (at most
  /// pi), whose swept sectors are seen as addWaypointPath sees them: a path of segments,
  /// arcs and rotations measured on the same terms as the waypoint path it smooths. One
  /// pass. Throws InvalidInputError for a non-finite pose (nothing is added then).
  void addSweptPath(const std::vector<Pose2>& poses, const FrustumSensor& sensor);

  const CoverageRaster& raster() const { return raster_; }

  /// How many separate times the cell with row-major index `index` was seen (saturating).
  std::uint16_t visits(std::size_t index) const { return visits_[index]; }

  /// True when the cell was seen at least once.
  bool seen(std::size_t index) const { return visits_[index] > 0; }

  /// The seen cells as a mask.
  CellMask seenMask() const;

  /// Seen share of the cells of `region`, in percent (the reported
  /// coverage_percent when `region` is the free area). Throws InvalidInputError when the
  /// region has no cell or the wrong size.
  double coveragePercent(const CellMask& region) const;

  /// Centres of up to `max_count` cells of `region` never seen, in row-major order, for
  /// diagnosing coverage gaps.
  std::vector<Point2> unseenCentres(const CellMask& region, std::size_t max_count) const;

  /// The heatmap grid (a copy, for plots and files).
  Heatmap heatmap() const;

 private:
  /// addTrajectory; with `sweep_rotations`, consecutive poses at the same position also
  /// see the sectors swept by the footprint's corners turning between their headings.
  void addPoses(const std::vector<Pose2>& poses, const FrustumSensor& sensor, bool sweep_rotations);

  /// The cells of one band of rows seen in a pass's latest step and in the current one, as
  /// disjoint row spans in row-major order.
  struct BandSteps {
    std::vector<CellSpan> previous;
    std::vector<CellSpan> current;
    std::vector<CellSpan> ordered;       ///< scratch: a step's spans put in order
    std::vector<std::size_t> row_start;  ///< scratch: where each row's spans go
  };

  /// Marks the cells of `spans` (reordered; all in the band's rows) as seen in the current
  /// step: a cell not seen in the step before starts a new visit. Costs the step's rows and
  /// its new cells, not its area, so densely sampled poses are cheap.
  void markStep(std::vector<CellSpan>& spans, BandSteps& band);

  CoverageRaster raster_;
  std::vector<std::uint16_t> visits_;
};

}  // namespace kinematic_coverage::core
