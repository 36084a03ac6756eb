#include "trajectory_generation_tools/replanning/remaining_area.h"

#include <algorithm>
#include <cmath>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/sweeps/coverage_raster.h"
#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"
#include "polygon_coverage_ros_bridge/sweeps/reachable_area.h"
#include "polygon_coverage_ros_bridge/sweeps/seen_area.h"
#include "trajectory_generation_tools/replanning/alpha_shape_triangles.h"
#include "trajectory_generation_tools/replanning/raster_contours.h"
#include "trajectory_generation_tools/replanning/region_simplification.h"
#include "trajectory_generation_tools/replanning/visited_history.h"

namespace kinematic_coverage::core {
namespace {

/// Raster cells per sweep spacing: fine enough that the remaining area's boundary is
/// placed well within a lane's reach, coarse enough to keep replanning fast.
constexpr double kCellsPerSweepSpacing = 64.0;
/// Largest raster; coarser cells beyond it.
constexpr double kMaxRasterCells = 4e6;

/// The complement of a mask.
CellMask inverted(const CellMask& mask) {
  CellMask result(mask.size());
  for (std::size_t i = 0; i < mask.size(); ++i) result[i] = mask[i] == 0 ? 1 : 0;
  return result;
}

}  // namespace

RemainingAreaCalculator::RemainingAreaCalculator(const RemainingAreaOptions& options)
    : options_(options) {}

RemainingArea RemainingAreaCalculator::compute(const PolygonWithHoles& free_area,
                                               const std::vector<Pose2>& visited) const {
  for (const Pose2& pose : visited) {
    if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.yaw)) {
      throw InvalidInputError("a visited pose has a non-finite coordinate");
    }
  }
  const CoverageRaster raster = rasterCovering(free_area);
  return fromSeen(raster, free_area,
                  seenMask(raster, visited, FrustumSensor::fromOptions(options_.sensor), nullptr));
}

RemainingArea RemainingAreaCalculator::compute(const PolygonWithHoles& free_area,
                                               const VisitedHistory& visited) const {
  const CoverageRaster raster = rasterCovering(free_area);
  return fromSeen(raster, free_area,
                  seenMask(raster, visited.recent(), visited.sensor(), &visited));
}

CoverageRaster RemainingAreaCalculator::rasterCovering(const PolygonWithHoles& free_area) const {
  const FrustumSensor sensor = FrustumSensor::fromOptions(options_.sensor);
  double min_x = free_area.hull.front().x(), max_x = min_x;
  double min_y = free_area.hull.front().y(), max_y = min_y;
  for (const Point2& p : free_area.hull) {
    min_x = std::min(min_x, p.x());
    max_x = std::max(max_x, p.x());
    min_y = std::min(min_y, p.y());
    max_y = std::max(max_y, p.y());
  }
  RasterResolution resolution;
  resolution.cell_size =
      std::max(sensor.sweepDistance() / kCellsPerSweepSpacing,
               std::sqrt((max_x - min_x + 1.0) * (max_y - min_y + 1.0) / kMaxRasterCells));
  resolution.max_cells = static_cast<std::size_t>(2 * kMaxRasterCells);
  return CoverageRaster::covering(free_area, resolution);
}

CellMask RemainingAreaCalculator::seenMask(const CoverageRaster& raster,
                                           const std::vector<Pose2>& recent,
                                           const FrustumSensor& sensor,
                                           const VisitedHistory* folded) const {
  CellMask seen(raster.cellCount(), 0);
  const ReplanningMethod method = options_.method;
  if (method == ReplanningMethod::kFootprint) {
    if (!recent.empty()) {
      SeenArea area(raster);
      area.addTrajectory(recent, sensor);
      seen = area.seenMask();
    }
    if (folded != nullptr) folded->markFoldedSeen(raster, seen);
    return seen;
  }
  std::vector<Point2> corners;
  if (folded != nullptr) {
    const std::vector<Point2>& kept =
        method == ReplanningMethod::kConvexHull ? folded->foldedHull() : folded->foldedCorners();
    corners.assign(kept.begin(), kept.end());
  }
  for (const Pose2& pose : recent) {
    for (const Point2& corner : sensor.footprint(pose)) corners.push_back(corner);
  }
  if (corners.empty()) return seen;
  if (method == ReplanningMethod::kConvexHull)
    return raster.rasterize(PolygonWithHoles{convexHull(corners), {}});
  std::vector<CellSpan> spans;
  for (const auto& triangle : alphaShapeTriangles(corners, options_.alpha)) {
    Ring ring(triangle.begin(), triangle.end());
    if (signedArea(ring) < 0.0) std::reverse(ring.begin(), ring.end());
    raster.appendConvexSpans(ring, spans);
  }
  for (const CellSpan& span : spans) {
    for (int column = span.begin; column < span.end; ++column) {
      seen[raster.index(span.row, column)] = 1;
    }
  }
  return seen;
}

RemainingArea RemainingAreaCalculator::fromSeen(const CoverageRaster& raster,
                                                const PolygonWithHoles& free_area,
                                                const CellMask& seen) const {
  const FrustumSensor sensor = FrustumSensor::fromOptions(options_.sensor);
  RemainingArea result;
  result.cell_size_m = raster.cellSize();
  const CellMask free = raster.rasterize(free_area);
  CellMask remaining(raster.cellCount(), 0);
  for (std::size_t i = 0; i < remaining.size(); ++i) {
    remaining[i] = free[i] != 0 && seen[i] == 0 ? 1 : 0;
    if (free[i] != 0 && seen[i] != 0) result.seen_area_m2 += raster.cellArea();
  }
  result.free_area_m2 = raster.area(free);
  result.remaining_area_m2 = raster.area(remaining);

  // Opening: parts narrower than the sliver width vanish, the rest keeps its shape.
  const double radius = 0.5 * options_.sliver_fraction * sensor.sweepDistance();
  CellMask opened = remaining;
  if (radius > 0.0) {
    const CellMask eroded = inverted(dilateMask(raster, inverted(remaining), radius));
    opened = dilateMask(raster, eroded, radius);
    for (std::size_t i = 0; i < opened.size(); ++i) opened[i] = opened[i] && remaining[i];
  }
  removeDiagonalPinches(raster, opened);
  for (const PolygonWithHoles& part : traceMaskContours(raster, opened)) {
    if (area(part) < std::max(options_.min_area, raster.cellArea())) {
      result.dropped.push_back({area(part), centroid(part)});
      continue;
    }
    PolygonWithHoles simplified = simplifyPolygon(
        part, std::max(options_.simplify_tolerance, std::sqrt(2.0) * raster.cellSize()));
    result.kept_area_m2 += area(simplified);
    result.parts.push_back(std::move(simplified));
  }
  return result;
}

}  // namespace kinematic_coverage::core
