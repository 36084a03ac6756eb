#include "trajectory_generation_tools/coverage/seen_area.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "trajectory_generation_tools/coverage/waypoint_path_poses.h"

namespace kinematic_coverage::core {
namespace {

/// Visits at which a cell's count saturates.
constexpr std::uint16_t kMaxVisits = std::numeric_limits<std::uint16_t>::max();

/// Longest arc (radians) replaced by a chord when sweeping a footprint corner's sector:
/// the chord loses 1 - cos(0.025), about 3e-4, of the radius.
constexpr double kSectorArcStep = 0.05;

/// Convex hull (counter-clockwise, Andrew's monotone chain) of two footprints' corners;
/// fewer than 3 vertices when they are collinear (a line sensor moving along its line).
Ring convexHull(const Ring& a, const Ring& b) {
  std::vector<Point2> points(a.begin(), a.end());
  points.insert(points.end(), b.begin(), b.end());
  std::sort(points.begin(), points.end(), [](const Point2& p, const Point2& q) {
    return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y());
  });
  Ring hull(2 * points.size());
  std::size_t k = 0;
  for (const Point2& p : points) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0.0) --k;
    hull[k++] = p;
  }
  const std::size_t lower = k + 1;
  for (auto it = points.rbegin() + 1; it != points.rend(); ++it) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], *it) <= 0.0) --k;
    hull[k++] = *it;
  }
  hull.resize(k > 1 ? k - 1 : k);
  return hull;
}

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
    : raster_(raster), recent_steps_(raster.cellCount(), 0), visits_(raster.cellCount(), 0) {}

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
  std::vector<CellSpan> spans;
  std::size_t step = 0;
  Ring previous = sensor.footprint(poses.front());
  if (poses.size() == 1) {
    raster_.appendConvexSpans(previous, spans);
    markStep(spans, step++ % 2);
  }
  for (std::size_t i = 1; i < poses.size(); ++i) {
    Ring current = sensor.footprint(poses[i]);
    spans.clear();
    if ((poses[i].position() - poses[i - 1].position()).norm() > kSamePositionTolerance) {
      raster_.appendConvexSpans(convexHull(previous, current), spans);
    } else {
      raster_.appendConvexSpans(previous, spans);
      raster_.appendConvexSpans(current, spans);
      if (sweep_rotations) {
        const double turn = wrapAngle(poses[i].yaw - poses[i - 1].yaw);
        for (const Point2& corner : previous) {
          raster_.appendConvexSpans(cornerSector(poses[i].position(), corner, turn), spans);
        }
      }
    }
    markStep(spans, step++ % 2);
    previous = std::move(current);
  }
  // The next pass starts afresh: what it sees again is a new visit.
  for (std::size_t parity = 0; parity < 2; ++parity) {
    for (const std::size_t i : recent_cells_[parity]) recent_steps_[i] = 0;
    recent_cells_[parity].clear();
  }
}

void SeenArea::markStep(const std::vector<CellSpan>& spans, std::size_t parity) {
  const std::uint8_t own = static_cast<std::uint8_t>(1u << parity);
  const std::uint8_t before = static_cast<std::uint8_t>(1u << (1 - parity));
  std::vector<std::size_t>& own_cells = recent_cells_[parity];
  // Forget the step two before this one, which had the same parity.
  for (const std::size_t i : own_cells) recent_steps_[i] &= static_cast<std::uint8_t>(~own);
  own_cells.clear();
  for (const CellSpan& span : spans) {
    const std::size_t begin = raster_.index(span.row, span.begin);
    const std::size_t end = raster_.index(span.row, span.end);
    for (std::size_t i = begin; i < end; ++i) {
      const std::uint8_t flags = recent_steps_[i];
      if ((flags & own) != 0) continue;
      if ((flags & before) == 0 && visits_[i] < kMaxVisits) ++visits_[i];
      recent_steps_[i] = static_cast<std::uint8_t>(flags | own);
      own_cells.push_back(i);
    }
  }
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
