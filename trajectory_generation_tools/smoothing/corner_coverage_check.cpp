#include "trajectory_generation_tools/smoothing/corner_coverage_check.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "polygon_coverage_ros_bridge/sweeps/coverage_raster.h"
#include "polygon_coverage_ros_bridge/sweeps/seen_area.h"

namespace kinematic_coverage::core {
namespace {

/// At most this many cells per side of the local raster; a larger corner gets coarser cells.
constexpr double kMaxCellsPerSide = 512.0;
/// Angle (rad) between the footprints of the in-place rotation, swept exactly between them.
constexpr double kRotationStep = 0.05;

Pose2 poseAt(const Point2& p, const Point2& heading) {
  return {p.x(), p.y(), std::atan2(heading.y(), heading.x())};
}

/// An axis-aligned box, grown point by point.
struct Box {
  double x0 = std::numeric_limits<double>::infinity();
  double y0 = std::numeric_limits<double>::infinity();
  double x1 = -std::numeric_limits<double>::infinity();
  double y1 = -std::numeric_limits<double>::infinity();

  void add(const Point2& p) {
    x0 = std::min(x0, p.x());
    x1 = std::max(x1, p.x());
    y0 = std::min(y0, p.y());
    y1 = std::max(y1, p.y());
  }

  /// Adds the arc's bounding box: its ends and the points of its circle at the four axis
  /// directions that its sweep passes.
  void addArc(const PathPrimitive& arc) {
    add(arc.start());
    add(arc.end());
    if (arc.kind() != PrimitiveKind::kArc) return;  // a straight run of a bulb turn
    const double sweep = std::abs(arc.sweep());
    for (int quarter = 0; quarter < 4; ++quarter) {
      const double angle = 0.5 * M_PI * quarter;
      const double from_start =
          arc.sweep() >= 0.0 ? angle - arc.startAngle() : arc.startAngle() - angle;
      if (std::fmod(std::fmod(from_start, 2.0 * M_PI) + 2.0 * M_PI, 2.0 * M_PI) <= sweep) {
        add(arc.centre() + arc.radius() * Point2(std::cos(angle), std::sin(angle)));
      }
    }
  }
};

}  // namespace

CornerCoverageCheck::CornerCoverageCheck(const BoundaryEdgeIndex& index,
                                         const FrustumSensor& sensor)
    : index_(index), sensor_(sensor) {
  const double shorter =
      sensor.length() > 0.0 ? std::min(sensor.width(), sensor.length()) : sensor.width();
  cell_size_ = shorter / kCellsPerFootprint;
}

double CornerCoverageCheck::lostArea(const std::vector<Point2>& corner_path,
                                     const CornerSmoothing& smoothing) const {
  return measure(corner_path, smoothing).area;
}

bool CornerCoverageCheck::preserves(const std::vector<Point2>& corner_path,
                                    const CornerSmoothing& smoothing) const {
  const Loss loss = measure(corner_path, smoothing);
  return loss.area <= kToleratedCells * loss.cell_area;
}

CornerCoverageCheck::Loss CornerCoverageCheck::measure(const std::vector<Point2>& corner_path,
                                                       const CornerSmoothing& smoothing) const {
  if (smoothing.arcs.empty() || corner_path.size() < 3) return {};
  const Point2& a = corner_path[0];
  const Point2& first = corner_path[1];
  const Point2& last = corner_path[corner_path.size() - 2];
  const Point2& c = corner_path.back();
  const Point2 in = (first - a).normalized();
  const Point2 out = (c - last).normalized();
  const double reach = 0.5 * std::hypot(sensor_.width(), sensor_.length());
  const Point2 before = first - std::min((first - a).norm(), smoothing.entry_distance + reach) * in;
  const Point2 after = last + std::min((c - last).norm(), smoothing.exit_distance + reach) * out;

  // The sharp version: the same legs, turning in place at every corner.
  std::vector<Pose2> sharp_path{poseAt(before, in)};
  for (std::size_t k = 1; k + 1 < corner_path.size(); ++k) {
    sharp_path.push_back(poseAt(corner_path[k], corner_path[k] - corner_path[k - 1]));
  }
  sharp_path.push_back(poseAt(after, out));

  // The raster covers both versions with a footprint's reach around them.
  Box box;
  for (const Pose2& pose : sharp_path) box.add(pose.position());
  for (const PathPrimitive& arc : smoothing.arcs) box.addArc(arc);
  const double margin = reach + 2.0 * cell_size_;
  const double extent = std::max(box.x1 - box.x0, box.y1 - box.y0) + 2.0 * margin;
  const double cell = std::max(cell_size_, extent / kMaxCellsPerSide);
  const int columns = static_cast<int>(std::ceil((box.x1 - box.x0 + 2.0 * margin) / cell));
  const int rows = static_cast<int>(std::ceil((box.y1 - box.y0 + 2.0 * margin) / cell));
  const CoverageRaster raster(Point2(box.x0 - margin, box.y0 - margin), cell, columns, rows);

  // The smoothed version's poses: straight legs need only their ends (a translated convex
  // footprint sweeps the hull of its end footprints). Along an arc the footprint turns
  // about the arc's centre, its points on circles of radius at most rho = radius + reach;
  // the hull of two footprints a step of dtheta apart misses at most the sagitta
  // rho dtheta^2 / 8 of those circles, so steps of 2 sqrt(cell / rho) keep that within half
  // a cell (and at most kRotationStep, as the sharp version's rotation). The raster's size
  // limit bounds the samples however small the footprint: at most 2 pi / kRotationStep for
  // an arc of a radius within the raster, fewer for a flatter one.
  std::vector<Pose2> smoothed{poseAt(before, in)};
  for (const PathPrimitive& arc : smoothing.arcs) {
    const int pieces = sweptArcPieces(arc.sweep(), arc.radius() + reach, cell, kRotationStep);
    for (int k = 0; k <= pieces; ++k) smoothed.push_back(arc.poseAt(double(k) / pieces));
  }
  smoothed.push_back(poseAt(after, out));

  SeenArea sharp(raster);
  sharp.addWaypointPath(sharp_path, sensor_, kRotationStep);
  SeenArea smooth(raster);
  smooth.addTrajectory(smoothed, sensor_);
  std::size_t lost = 0;
  for (std::size_t i = 0; i < raster.cellCount(); ++i) {
    if (sharp.seen(i) && !smooth.seen(i) && index_.inside(raster.cellCentre(i))) ++lost;
  }
  return {static_cast<double>(lost) * raster.cellArea(), raster.cellArea()};
}

}  // namespace kinematic_coverage::core
