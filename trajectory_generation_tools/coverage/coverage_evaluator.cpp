#include "trajectory_generation_tools/coverage/coverage_evaluator.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <sstream>
#include <utility>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/sweeps/reachable_area.h"

namespace kinematic_coverage::core {
namespace {

const FrustumSensor& requireValid(const FrustumSensor& sensor) {
  if (!(sensor.width() > 0.0) || !std::isfinite(sensor.width()) || !(sensor.length() >= 0.0) ||
      !std::isfinite(sensor.length())) {
    std::ostringstream message;
    message << "coverage: footprint " << sensor.width() << " m x " << sensor.length()
            << " m must have a finite width > 0 and a finite length >= 0";
    throw InvalidInputError(message.str());
  }
  return sensor;
}

/// The polygon turned by `angle` about the origin.
PolygonWithHoles turned(const PolygonWithHoles& polygon, double angle) {
  if (angle == 0.0) return polygon;
  const Eigen::Rotation2Dd rotation(angle);
  PolygonWithHoles result = polygon;
  for (Point2& p : result.hull) p = rotation * p;
  for (Ring& hole : result.holes) {
    for (Point2& p : hole) p = rotation * p;
  }
  return result;
}

std::vector<PolygonWithHoles> turned(const std::vector<PolygonWithHoles>& parts, double angle) {
  std::vector<PolygonWithHoles> result;
  for (const PolygonWithHoles& part : parts) result.push_back(turned(part, angle));
  return result;
}

}  // namespace

struct CoverageEvaluator::FreeFractions {
  explicit FreeFractions(PolygonWithHoles area) : turned_free_area(std::move(area)) {}
  std::once_flag computed;
  PolygonWithHoles turned_free_area;
  CellFractions fractions;
};

RasterResolution reportingResolution() {
  RasterResolution resolution;
  resolution.cell_size = 0.0;
  resolution.relative_accuracy = 1e-3;
  resolution.min_cell_size = kReportingCellSize;
  resolution.floor_cells = kReportingFloorCells;
  return resolution;
}

CoverageEvaluator::CoverageEvaluator(const PolygonWithHoles& free_area,
                                     const std::vector<PolygonWithHoles>& offset_parts,
                                     const FrustumSensor& sensor,
                                     const RasterResolution& resolution, double grid_angle)
    : sensor_(requireValid(sensor)),
      grid_angle_(grid_angle),
      to_raster_(Eigen::Rotation2Dd(-grid_angle).toRotationMatrix()),
      from_raster_(Eigen::Rotation2Dd(grid_angle).toRotationMatrix()),
      free_fractions_(std::make_shared<FreeFractions>(turned(free_area, -grid_angle))),
      raster_(CoverageRaster::covering(free_fractions_->turned_free_area, resolution)),
      free_area_(raster_.rasterize(free_fractions_->turned_free_area)) {
  const std::vector<PolygonWithHoles> raster_parts = turned(offset_parts, -grid_angle);
  offset_free_area_ = raster_.rasterize(raster_parts);
  if (CoverageRaster::countCells(offset_free_area_) == 0) {
    std::ostringstream message;
    message << "coverage: the offset free area covers no cell of the " << raster_.cellSize()
            << " m raster";
    throw InvalidInputError(message.str());
  }
  reachable_area_ = kinematic_coverage::core::reachableArea(raster_, free_area_, offset_free_area_,
                                                            raster_parts, sensor_.length());
}

const CellFractions& CoverageEvaluator::freeFractions() const {
  FreeFractions& lazy = *free_fractions_;
  std::call_once(lazy.computed,
                 [&] { lazy.fractions = raster_.areaFractions(lazy.turned_free_area); });
  return lazy.fractions;
}

Point2 CoverageEvaluator::toRaster(const Point2& p) const {
  return grid_angle_ == 0.0 ? p : Point2(to_raster_ * p);
}

Point2 CoverageEvaluator::fromRaster(const Point2& p) const {
  return grid_angle_ == 0.0 ? p : Point2(from_raster_ * p);
}

std::vector<Pose2> CoverageEvaluator::toRaster(const std::vector<Pose2>& poses) const {
  if (grid_angle_ == 0.0) return poses;
  std::vector<Pose2> result;
  result.reserve(poses.size());
  for (const Pose2& pose : poses) {
    const Point2 p = toRaster(pose.position());
    result.push_back({p.x(), p.y(), pose.yaw - grid_angle_});
  }
  return result;
}

SeenArea CoverageEvaluator::seeTrajectory(const std::vector<Pose2>& poses) const {
  SeenArea seen(raster_);
  seen.addTrajectory(toRaster(poses), sensor_);
  return seen;
}

SeenArea CoverageEvaluator::seeWaypointPath(const std::vector<Pose2>& waypoints,
                                            double rotation_step) const {
  SeenArea seen(raster_);
  seen.addWaypointPath(toRaster(waypoints), sensor_, rotation_step);
  return seen;
}

void CoverageEvaluator::requireOwnRaster(const SeenArea& seen) const {
  if (seen.raster().cellCount() != raster_.cellCount() ||
      seen.raster().cellSize() != raster_.cellSize() ||
      seen.raster().origin() != raster_.origin()) {
    throw InvalidInputError("coverage: the seen area was made on another raster");
  }
}

void CoverageEvaluator::restrictReachableArea(const std::vector<PolygonWithHoles>& region) {
  const CellMask inside = raster_.rasterize(turned(region, -grid_angle_));
  for (std::size_t i = 0; i < inside.size(); ++i) reachable_area_[i] &= inside[i];
}

Heatmap CoverageEvaluator::heatmapOn(const SeenArea& seen, const CoverageRaster& grid) const {
  requireOwnRaster(seen);
  Heatmap heatmap{grid.origin(), grid.cellSize(), grid.columns(), grid.rows(),
                  std::vector<std::uint16_t>(grid.cellCount(), 0)};
  for (std::size_t index = 0; index < grid.cellCount(); ++index) {
    if (const std::optional<std::size_t> cell = cellAt(grid.cellCentre(index))) {
      heatmap.visits[index] = seen.visits(*cell);
    }
  }
  return heatmap;
}

std::optional<std::size_t> CoverageEvaluator::cellAt(const Point2& p) const {
  const Point2 q = (toRaster(p) - raster_.origin()) / raster_.cellSize();
  if (!(q.x() >= 0.0 && q.y() >= 0.0 && q.x() < raster_.columns() && q.y() < raster_.rows())) {
    return std::nullopt;
  }
  return raster_.index(static_cast<int>(q.y()), static_cast<int>(q.x()));
}

std::optional<UnseenRegion> CoverageEvaluator::largestUnseenRegion(const SeenArea& seen) const {
  std::vector<UnseenRegion> regions = unseenRegions(seen, 0);
  if (regions.empty()) return std::nullopt;
  return std::move(regions.front());
}

std::vector<std::size_t> CoverageEvaluator::unseenCells(const SeenArea& seen, double join_distance,
                                                        CellMask* joined) const {
  // One pass over the grid (the unseen cells are usually a sliver of it); cells within the
  // join distance of each other are connected through the unseen cells grown by half of it.
  std::vector<std::size_t> cells;
  for (std::size_t i = 0; i < raster_.cellCount(); ++i) {
    if (unseenAt(seen, i)) cells.push_back(i);
  }
  if (join_distance > 0.0) {
    CellMask mask(raster_.cellCount(), 0);
    for (std::size_t i : cells) mask[i] = 1;
    *joined = dilateMask(raster_, mask, 0.5 * join_distance);
  }
  return cells;
}

std::vector<UnseenRegion> CoverageEvaluator::unseenRegions(const SeenArea& seen,
                                                           std::size_t samples_per_region,
                                                           double join_distance) const {
  requireOwnRaster(seen);
  const auto unseen = [&](std::size_t i) { return unseenAt(seen, i); };
  CellMask joined;
  const std::vector<std::size_t> unseen_cells = unseenCells(seen, join_distance, &joined);
  const auto connected = [&](std::size_t i) { return joined.empty() ? unseen(i) : joined[i] != 0; };
  // Flood fill over the connected cells, 8-connected; each cell is visited once.
  std::vector<std::uint8_t> done(raster_.cellCount(), 0);
  std::vector<std::size_t> stack;
  std::vector<std::size_t> filled;
  std::vector<UnseenRegion> regions;
  const int columns = raster_.columns();
  const int rows = raster_.rows();
  for (const std::size_t first : unseen_cells) {
    if (done[first] != 0) continue;
    Point2 sum = Point2::Zero();
    Point2 low = Point2::Constant(std::numeric_limits<double>::infinity());
    Point2 high = -low;
    done[first] = 1;
    stack.assign(1, first);
    filled.clear();
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      const int row = static_cast<int>(i / static_cast<std::size_t>(columns));
      const int column = static_cast<int>(i % static_cast<std::size_t>(columns));
      if (unseen(i)) {
        filled.push_back(i);
        const Point2 centre = fromRaster(raster_.cellCentre(i));
        sum += centre;
        low = low.cwiseMin(centre);
        high = high.cwiseMax(centre);
      }
      for (int dr = -1; dr <= 1; ++dr) {
        for (int dc = -1; dc <= 1; ++dc) {
          const int r = row + dr;
          const int c = column + dc;
          if (r < 0 || r >= rows || c < 0 || c >= columns) continue;
          const std::size_t j = raster_.index(r, c);
          if (done[j] != 0 || !connected(j)) continue;
          done[j] = 1;
          stack.push_back(j);
        }
      }
    }
    // The cells' centres grown by half a (turned) cell's diagonal: the cells themselves.
    const Point2 half = Point2::Constant(std::sqrt(0.5) * raster_.cellSize());
    low -= half;
    high += half;
    UnseenRegion region{static_cast<double>(filled.size()) * raster_.cellArea(),
                        sum / static_cast<double>(filled.size()),
                        {low, {high.x(), low.y()}, high, {low.x(), high.y()}},
                        {}};
    if (samples_per_region > 0) {
      const std::size_t stride = (filled.size() + samples_per_region - 1) / samples_per_region;
      for (std::size_t k = 0; k < filled.size(); k += stride) {
        region.samples.push_back(fromRaster(raster_.cellCentre(filled[k])));
      }
    }
    regions.push_back(std::move(region));
  }
  std::stable_sort(
      regions.begin(), regions.end(),
      [](const UnseenRegion& a, const UnseenRegion& b) { return a.area_m2 > b.area_m2; });
  return regions;
}

CoverageReport CoverageEvaluator::report(const SeenArea& seen) const {
  requireOwnRaster(seen);
  CoverageReport result;
  double free_cells = 0.0;
  double seen_free_cells = 0.0;
  double unreachable_cells = 0.0;
  std::size_t unseen_reachable = 0;
  const CellFractions& free_fractions = freeFractions();
  for (std::size_t i = 0; i < free_fractions.size(); ++i) {
    const double inside = free_fractions[i];
    free_cells += inside;
    if (seen.seen(i)) seen_free_cells += inside;
    if (reachable_area_[i] == 0) unreachable_cells += inside;
    if (reachable_area_[i] != 0 && !seen.seen(i)) ++unseen_reachable;
  }
  if (!(free_cells > 0.0)) {
    throw InvalidInputError("coverage: the free area covers no cell of the raster");
  }
  result.coverage_percent = 100.0 * seen_free_cells / free_cells;
  result.coverage_loss_percent = 100.0 - result.coverage_percent;
  result.reachable_coverage_percent = seen.coveragePercent(reachable_area_);
  result.unseen_reachable_area_m2 = static_cast<double>(unseen_reachable) * raster_.cellArea();
  result.unreachable_area_m2 = unreachable_cells * raster_.cellArea();
  return result;
}

LostArea CoverageEvaluator::lostArea(const SeenArea& reference, const SeenArea& seen) const {
  requireOwnRaster(reference);
  requireOwnRaster(seen);
  double free_cells = 0.0;
  double lost_cells = 0.0;
  std::size_t lost_reachable = 0;
  const CellFractions& free_fractions = freeFractions();
  for (std::size_t i = 0; i < free_fractions.size(); ++i) {
    free_cells += free_fractions[i];
    if (!reference.seen(i) || seen.seen(i)) continue;
    lost_cells += free_fractions[i];
    if (reachable_area_[i] != 0) ++lost_reachable;
  }
  if (!(free_cells > 0.0)) {
    throw InvalidInputError("coverage: the free area covers no cell of the raster");
  }
  return {lost_cells * raster_.cellArea(), static_cast<double>(lost_reachable) * raster_.cellArea(),
          100.0 * lost_cells / free_cells};
}

double waypointPathReachableCoveragePercent(const PolygonWithHoles& free_area,
                                            const std::vector<PolygonWithHoles>& offset_parts,
                                            const FrustumSensor& sensor,
                                            const std::vector<Pose2>& waypoints,
                                            const RasterResolution& resolution,
                                            double rotation_step) {
  const CoverageEvaluator evaluator(free_area, offset_parts, sensor, resolution);
  return evaluator.seeWaypointPath(waypoints, rotation_step)
      .coveragePercent(evaluator.reachableArea());
}

}  // namespace kinematic_coverage::core
