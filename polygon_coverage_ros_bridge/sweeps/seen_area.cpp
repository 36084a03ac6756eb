#include "polygon_coverage_ros_bridge/sweeps/seen_area.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "polygon_coverage_ros_bridge/base/parallel_for.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/sweeps/waypoint_path_poses.h"

namespace kinematic_coverage::core {
namespace {

/// Visits at which a cell's count saturates.
constexpr std::uint16_t kMaxVisits = std::numeric_limits<std::uint16_t>::max();

/// Steps from which a pass is marked on every hardware thread (its step areas, then bands
/// of rows): shorter ones, such as a smoothed corner's check, cost less than starting threads.
constexpr std::size_t kBandedMinSteps = 1000;
/// Bands of rows per thread, so that bands of uneven work (open water beside a dense
/// shore) balance.
constexpr std::size_t kBandsPerThread = 4;

/// Longest arc (radians) replaced by a chord when sweeping a footprint corner's sector:
/// the chord loses 1 - cos(0.025), about 3e-4, of the radius.
constexpr double kSectorArcStep = 0.05;

/// The circular sector that `corner` sweeps turning by `turn` (|turn| <= pi) about
/// `centre`, as a convex polygon with vertices on the arc at most kSectorArcStep apart.
Ring cornerSector(const Point2& centre, const Point2& corner, double turn) {
  const int pieces = static_cast<int>(std::ceil(std::abs(turn) / kSectorArcStep));
  Ring sector{centre};
  if (pieces == 0) return sector;
  const Point2 arm = corner - centre;
  for (int k = 0; k <= pieces; ++k) {
    const double angle = turn * k / pieces;
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    sector.push_back(centre + Point2(c * arm.x() - s * arm.y(), s * arm.x() + c * arm.y()));
  }
  return sector;
}

void requireRegionSize(const CoverageRaster& raster, const CellMask& region) {
  if (region.size() != raster.cellCount()) {
    std::ostringstream message;
    message << "coverage: the region mask has " << region.size() << " cells, the grid "
            << raster.cellCount();
    throw InvalidInputError(message.str());
  }
}

}  // namespace

int sweptArcPieces(double sweep, double farthest, double cell_size, double max_step) {
  const double step = std::min(max_step, 2.0 * std::sqrt(cell_size / farthest));
  return std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / step)));
}

SeenArea::SeenArea(const CoverageRaster& raster)
    : raster_(raster), visits_(raster.cellCount(), 0) {}

void SeenArea::addTrajectory(const std::vector<Pose2>& poses, const FrustumSensor& sensor) {
  addPoses(poses, sensor, false);
}

void SeenArea::addWaypointPath(const std::vector<Pose2>& waypoints, const FrustumSensor& sensor,
                               double rotation_step) {
  addPoses(waypointPathPoses(waypoints, rotation_step), sensor, true);
}

void SeenArea::addSweptPath(const std::vector<Pose2>& poses, const FrustumSensor& sensor) {
  addPoses(poses, sensor, true);
}

void SeenArea::addPoses(const std::vector<Pose2>& poses, const FrustumSensor& sensor,
                        bool sweep_rotations) {
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const Pose2& pose = poses[i];
    if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.yaw)) {
      std::ostringstream message;
      message << "coverage: pose " << i << " has a non-finite coordinate or heading";
      throw InvalidInputError(message.str());
    }
  }
  if (poses.empty()) return;
  // Each step's area as convex polygons: one pose's footprint, the hull of two footprints
  // apart, or a rotation's footprints and corner sectors.
  const std::size_t steps = std::max<std::size_t>(1, poses.size() - 1);
  std::vector<std::vector<Ring>> step_areas(steps);
  const bool parallel = steps >= kBandedMinSteps;
  if (poses.size() == 1) step_areas.front() = {sensor.footprint(poses.front())};
  const auto stepArea = [&](std::size_t k, std::size_t) {
    const Pose2& from = poses[k];
    const Pose2& to = poses[k + 1];
    Ring previous = sensor.footprint(from);
    Ring current = sensor.footprint(to);
    std::vector<Ring>& area = step_areas[k];
    if ((to.position() - from.position()).norm() > kSamePositionTolerance) {
      std::vector<Point2> corners(previous.begin(), previous.end());
      corners.insert(corners.end(), current.begin(), current.end());
      area.push_back(convexHull(std::move(corners)));
      return;
    }
    if (sweep_rotations) {
      const double turn = wrapAngle(to.yaw - from.yaw);
      for (const Point2& corner : previous) {
        area.push_back(cornerSector(to.position(), corner, turn));
      }
    }
    area.insert(area.begin(), {std::move(previous), std::move(current)});
  };
  if (poses.size() > 1) {
    parallelForOnThreads(poses.size() - 1, parallel ? 0 : 1, stepArea);
  }
  // Then the steps in order, in bands of rows on every thread.
  const std::size_t bands = parallel ? kBandsPerThread * parallelThreadCount(steps) : 1;
  const int rows = raster_.rows();
  parallelForOnThreads(bands, parallel ? 0 : 1, [&](std::size_t band, std::size_t) {
    const int first_row = static_cast<int>(static_cast<long long>(rows) * band / bands);
    const int end_row = static_cast<int>(static_cast<long long>(rows) * (band + 1) / bands);
    if (first_row >= end_row) return;
    BandSteps cells;
    std::vector<CellSpan> spans;
    std::vector<CellSpan> end_footprint;  // of the latest step, when it was a rotation
    bool end_footprint_known = false;
    for (const std::vector<Ring>& area : step_areas) {
      spans.clear();
      std::size_t next_ring = 0;
      if (area.size() >= 2) {
        // A rotation in place: its start and end footprints first; the start one is the
        // end one of the step before when that was a rotation too.
        if (end_footprint_known) {
          spans = end_footprint;
        } else {
          raster_.appendConvexSpans(area[0], spans, first_row, end_row);
        }
        end_footprint.clear();
        raster_.appendConvexSpans(area[1], end_footprint, first_row, end_row);
        spans.insert(spans.end(), end_footprint.begin(), end_footprint.end());
        next_ring = 2;
      }
      end_footprint_known = area.size() >= 2;
      for (std::size_t r = next_ring; r < area.size(); ++r) {
        raster_.appendConvexSpans(area[r], spans, first_row, end_row);
      }
      markStep(spans, cells);
    }
  });
}

void SeenArea::markStep(std::vector<CellSpan>& spans, BandSteps& band) {
  // The step's cells as disjoint spans in row-major order (one convex area's spans come
  // in order already; several areas' are put in order by row, then by begin in each row).
  const auto row_major = [](const CellSpan& a, const CellSpan& b) {
    return a.row < b.row || (a.row == b.row && a.begin < b.begin);
  };
  if (!std::is_sorted(spans.begin(), spans.end(), row_major)) {
    int low = spans.front().row;
    int high = low;
    for (const CellSpan& span : spans) {
      low = std::min(low, span.row);
      high = std::max(high, span.row);
    }
    std::vector<std::size_t>& row_start = band.row_start;
    row_start.assign(static_cast<std::size_t>(high - low) + 2, 0);
    for (const CellSpan& span : spans) ++row_start[static_cast<std::size_t>(span.row - low) + 1];
    for (std::size_t r = 1; r < row_start.size(); ++r) row_start[r] += row_start[r - 1];
    std::vector<CellSpan>& ordered = band.ordered;
    ordered.resize(spans.size());
    for (const CellSpan& span : spans) {
      ordered[row_start[static_cast<std::size_t>(span.row - low)]++] = span;
    }
    // row_start[r] is now where row r + 1 begins; each row's few spans by begin.
    std::size_t begin = 0;
    for (std::size_t r = 0; r + 1 < row_start.size(); ++r) {
      const std::size_t end = row_start[r];
      for (std::size_t i = begin + 1; i < end; ++i) {
        for (std::size_t j = i; j > begin && ordered[j].begin < ordered[j - 1].begin; --j) {
          std::swap(ordered[j], ordered[j - 1]);
        }
      }
      begin = end;
    }
    spans.swap(ordered);
  }
  std::vector<CellSpan>& step_cells = band.current;
  const std::vector<CellSpan>& previous_step_cells = band.previous;
  step_cells.clear();
  for (const CellSpan& span : spans) {
    if (span.begin >= span.end) continue;
    CellSpan* last = step_cells.empty() ? nullptr : &step_cells.back();
    if (last != nullptr && last->row == span.row && span.begin <= last->end) {
      last->end = std::max(last->end, span.end);
    } else {
      step_cells.push_back(span);
    }
  }
  // A new visit to the cells of this step outside the step before: per span, the gaps
  // between the previous step's spans that overlap it.
  const auto visit = [this](int row, int begin, int end) {
    const std::size_t first = raster_.index(row, begin);
    const std::size_t last = raster_.index(row, end);
    for (std::size_t i = first; i < last; ++i) {
      if (visits_[i] < kMaxVisits) ++visits_[i];
    }
  };
  std::size_t next = 0;  // the first previous span not wholly before the current one
  for (const CellSpan& span : step_cells) {
    while (next < previous_step_cells.size() && (previous_step_cells[next].row < span.row ||
                                                 (previous_step_cells[next].row == span.row &&
                                                  previous_step_cells[next].end <= span.begin))) {
      ++next;
    }
    int from = span.begin;
    for (std::size_t k = next;
         k < previous_step_cells.size() && previous_step_cells[k].row == span.row &&
         previous_step_cells[k].begin < span.end;
         ++k) {
      if (previous_step_cells[k].begin > from) visit(span.row, from, previous_step_cells[k].begin);
      from = std::max(from, previous_step_cells[k].end);
    }
    if (from < span.end) visit(span.row, from, span.end);
  }
  std::swap(band.previous, band.current);
}

CellMask SeenArea::seenMask() const {
  CellMask mask(visits_.size(), 0);
  for (std::size_t i = 0; i < visits_.size(); ++i) mask[i] = visits_[i] > 0 ? 1 : 0;
  return mask;
}

double SeenArea::coveragePercent(const CellMask& region) const {
  requireRegionSize(raster_, region);
  std::size_t region_cells = 0;
  std::size_t seen_cells = 0;
  for (std::size_t i = 0; i < region.size(); ++i) {
    if (region[i] == 0) continue;
    ++region_cells;
    if (visits_[i] > 0) ++seen_cells;
  }
  if (region_cells == 0) {
    std::ostringstream message;
    message << "coverage: the region covers no cell of the " << raster_.cellSize() << " m raster";
    throw InvalidInputError(message.str());
  }
  return 100.0 * static_cast<double>(seen_cells) / static_cast<double>(region_cells);
}

std::vector<Point2> SeenArea::unseenCentres(const CellMask& region, std::size_t max_count) const {
  requireRegionSize(raster_, region);
  std::vector<Point2> centres;
  for (std::size_t i = 0; i < region.size() && centres.size() < max_count; ++i) {
    if (region[i] != 0 && visits_[i] == 0) centres.push_back(raster_.cellCentre(i));
  }
  return centres;
}

Heatmap SeenArea::heatmap() const {
  return {raster_.origin(), raster_.cellSize(), raster_.columns(), raster_.rows(), visits_};
}

}  // namespace kinematic_coverage::core
