#include "trajectory_generation_tools/smoothing/path_coverage_check.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"
#include "polygon_coverage_ros_bridge/sweeps/reachable_area.h"
#include "polygon_coverage_ros_bridge/sweeps/waypoint_path_poses.h"

namespace kinematic_coverage::core {
namespace {

/// Largest angle (rad) between the sampled poses of an arc (also bounded by the raster's
/// cells below) and of an in-place rotation, whose sectors are swept exactly in between.
constexpr double kArcStep = 0.05;
/// Metres the chords bounding a clothoid's extent may stray from it.
constexpr double kClothoidExtentTolerance = 1e-3;
constexpr double kRotationStep = kDefaultRotationStep;

/// The poses along `primitives` that SeenArea::addSweptPath measures: a segment's ends (a
/// translated footprint sweeps the hull of its end footprints), an arc's samples within
/// half a cell of what it sweeps (sweptArcPieces), a rotation's steps.
std::vector<Pose2> sweptPoses(const std::vector<PathPrimitive>& primitives, double cell,
                              double reach) {
  std::vector<Pose2> poses;
  for (const PathPrimitive& primitive : primitives) {
    int pieces = 1;
    if (primitive.kind() == PrimitiveKind::kArc) {
      pieces = sweptArcPieces(primitive.sweep(), primitive.radius() + reach, cell, kArcStep);
    } else if (primitive.kind() == PrimitiveKind::kClothoid) {
      // Its pieces sweep no more than arcs of its tightest radius turning as fast.
      pieces = sweptArcPieces(primitive.length() * primitive.curvature(),
                              primitive.radius() + reach, cell, kArcStep);
    } else if (primitive.kind() == PrimitiveKind::kRotation) {
      pieces =
          std::max(1, static_cast<int>(std::ceil(std::abs(primitive.turnAngle()) / kRotationStep)));
    }
    for (int k = poses.empty() ? 0 : 1; k <= pieces; ++k) {
      poses.push_back(primitive.poseAt(static_cast<double>(k) / pieces));
    }
  }
  return poses;
}

using Box = Eigen::AlignedBox2d;

/// `box` grown by `margin` on every side.
Box grown(const Box& box, double margin) {
  return Box(Point2(box.min().array() - margin), Point2(box.max().array() + margin));
}

/// A box holding the path of `primitive` (an arc's whole circle).
Box extentOf(const PathPrimitive& primitive) {
  Box box;
  box.extend(primitive.start());
  box.extend(primitive.end());
  if (primitive.kind() == PrimitiveKind::kArc) {
    box.extend(Point2(primitive.centre().array() - primitive.radius()));
    box.extend(Point2(primitive.centre().array() + primitive.radius()));
  }
  if (primitive.kind() == PrimitiveKind::kClothoid) {
    for (const Point2& p : primitive.polyline(kClothoidExtentTolerance)) box.extend(p);
    box = grown(box, kClothoidExtentTolerance);
  }
  return box;
}

/// The box holding `stretch`, grown by `near`: where its lost cells can lie.
Box nearBox(const ReplacedStretch& stretch, double near) {
  Box box;
  for (const Point2& p : stretch) box.extend(p);
  return grown(box, near);
}

/// True when the two lists hold the same primitives, exactly.
bool samePrimitives(const std::vector<PathPrimitive>& a, const std::vector<PathPrimitive>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](const PathPrimitive& p, const PathPrimitive& q) {
                      return p.kind() == q.kind() && p.start() == q.start() && p.end() == q.end() &&
                             p.centre() == q.centre() && p.radius() == q.radius() &&
                             p.startAngle() == q.startAngle() && p.sweep() == q.sweep() &&
                             p.turnAngle() == q.turnAngle();
                    });
}

/// The cells of `raster` (rows and columns, inclusive) under `box`.
struct CellWindow {
  int first_column = 0;
  int last_column = -1;
  int first_row = 0;
  int last_row = -1;

  bool empty() const { return first_column > last_column || first_row > last_row; }
};

CellWindow cellWindow(const CoverageRaster& raster, const Box& box) {
  const double cell = raster.cellSize();
  const Point2& origin = raster.origin();
  CellWindow window;
  window.first_column =
      std::max(0, static_cast<int>(std::floor((box.min().x() - origin.x()) / cell)));
  window.last_column = std::min(raster.columns() - 1,
                                static_cast<int>(std::floor((box.max().x() - origin.x()) / cell)));
  window.first_row = std::max(0, static_cast<int>(std::floor((box.min().y() - origin.y()) / cell)));
  window.last_row = std::min(raster.rows() - 1,
                             static_cast<int>(std::floor((box.max().y() - origin.y()) / cell)));
  return window;
}

/// The cells of `window` that are reachable, that `sharp` sees and `seen_now(row, column)`
/// does not, and whose centres lie within `near` of `stretch`.
template <typename SeenNow>
std::size_t lostCellsIn(const CoverageRaster& raster, const CellWindow& window,
                        const CellMask& reachable, const SeenArea& sharp,
                        const ReplacedStretch& stretch, double near, SeenNow seen_now) {
  std::size_t lost = 0;
  for (int row = window.first_row; row <= window.last_row; ++row) {
    for (int column = window.first_column; column <= window.last_column; ++column) {
      const std::size_t i = raster.index(row, column);
      if (reachable[i] == 0 || !sharp.seen(i) || seen_now(row, column)) continue;
      const Point2 centre = raster.cellCentre(i);
      for (std::size_t k = 0; k + 1 < stretch.size(); ++k) {
        if (distanceToSegment(centre, stretch[k], stretch[k + 1]) <= near) {
          ++lost;
          break;
        }
      }
    }
  }
  return lost;
}

}  // namespace

PathCoverageCheck::PathCoverageCheck(const PolygonWithHoles& free_area, double wall_distance,
                                     const std::vector<PolygonWithHoles>& exact_parts,
                                     const FrustumSensor& sensor,
                                     const std::vector<Point2>& waypoints, CoverageSafeArea guarded)
    : sensor_(sensor) {
  if (!(wall_distance >= 0.0) || !std::isfinite(wall_distance)) {
    throw InvalidInputError("coverage-safe smoothing: wall distance " +
                            std::to_string(wall_distance) + " must be finite and >= 0");
  }
  reach_ = 0.5 * std::hypot(sensor.width(), sensor.length());
  if (waypoints.empty()) return;
  const double shorter =
      sensor.length() > 0.0 ? std::min(sensor.width(), sensor.length()) : sensor.width();
  Point2 low = waypoints.front();
  Point2 high = low;
  for (const Point2& p : waypoints) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  // Room for what the path sees and for the walls that shape the reachable area there.
  const Point2 margin = Point2::Constant(reach_ + wall_distance + 0.5 * sensor.length() + shorter);
  low -= margin;
  const Point2 size = high + margin - low;
  const double cell =
      std::max(std::min(shorter / kCellsPerFootprint,
                        std::sqrt(size.x() * size.y() / static_cast<double>(kFloorCells))),
               std::sqrt(size.x() * size.y() / static_cast<double>(kMaxCells)));
  raster_.emplace(low, cell, std::max(1, static_cast<int>(std::ceil(size.x() / cell))),
                  std::max(1, static_cast<int>(std::ceil(size.y() / cell))));

  if (free_area.hull.empty()) {
    reachable_.assign(raster_->cellCount(), 1);
  } else if (guarded == CoverageSafeArea::kFree) {
    reachable_ = raster_->rasterize(free_area);
  } else {
    // The exact offset, as the coverage report measures the reachable area.
    const std::vector<PolygonWithHoles> parts =
        exact_parts.empty()
            ? exactOffsetParts(free_area, wall_distance,
                               computeOffsetFreeArea(free_area, wall_distance).parts)
            : exact_parts;
    reachable_ = reachableArea(*raster_, raster_->rasterize(free_area), raster_->rasterize(parts),
                               parts, sensor.length());
  }

  rotations_.resize(waypoints.size());
  for (std::size_t k = 0; k + 1 < waypoints.size(); ++k) {
    legs_.push_back(PathPrimitive::segment(waypoints[k], waypoints[k + 1]));
    if (k == 0) continue;
    const Point2 in = waypoints[k] - waypoints[k - 1];
    const Point2 out = waypoints[k + 1] - waypoints[k];
    const double turn = std::atan2(in.x() * out.y() - in.y() * out.x(), in.dot(out));
    if (turn != 0.0 && in.norm() > kSamePositionTolerance && out.norm() > kSamePositionTolerance) {
      rotations_[k] = PathPrimitive::rotation(waypoints[k], std::atan2(in.y(), in.x()), turn);
    }
  }

  // waypointPathPoses takes each leg's heading from the positions; a yaw is used only
  // for a path at a single position.
  std::vector<Pose2> path;
  for (const Point2& p : waypoints) path.push_back({p.x(), p.y(), 0.0});
  sharp_.emplace(*raster_);
  sharp_->addWaypointPath(path, sensor_);
  std::size_t seen_reachable = 0;
  for (std::size_t i = 0; i < reachable_.size(); ++i) {
    if (reachable_[i] != 0 && sharp_->seen(i)) ++seen_reachable;
  }
  tolerated_lost_cells_ =
      static_cast<std::size_t>(kToleratedLostShare * static_cast<double>(seen_reachable));
}

std::vector<std::size_t> PathCoverageCheck::lostCells(
    const std::vector<PathPrimitive>& primitives, const std::vector<ReplacedStretch>& stretches) {
  std::vector<std::size_t> lost(stretches.size(), 0);
  if (!raster_) return lost;
  // Lost cells lie within `near` of the stretches, the only places where the two paths
  // differ, and only primitives whose footprints reach that far from their own extent
  // can see them.
  const double near = reach_ + raster_->cellSize();
  std::vector<Box> boxes;
  for (const ReplacedStretch& stretch : stretches) boxes.push_back(nearBox(stretch, near));
  std::vector<Box> primitive_boxes;
  for (const PathPrimitive& primitive : primitives) {
    primitive_boxes.push_back(grown(extentOf(primitive), near));
  }

  // Stretches whose neighbourhood is unchanged keep their count; the others are measured.
  std::vector<std::size_t> unmeasured;
  std::vector<std::vector<PathPrimitive>> nearby(stretches.size());
  std::vector<bool> near_unmeasured(primitives.size(), false);
  for (std::size_t s = 0; s < stretches.size(); ++s) {
    std::vector<std::size_t> near_primitives;
    for (std::size_t k = 0; k < primitives.size(); ++k) {
      if (primitive_boxes[k].intersects(boxes[s])) {
        nearby[s].push_back(primitives[k]);
        near_primitives.push_back(k);
      }
    }
    const auto known = std::find_if(measured_.begin(), measured_.end(), [&](const auto& entry) {
      return entry.stretch == stretches[s] && samePrimitives(entry.nearby, nearby[s]);
    });
    if (known != measured_.end()) {
      lost[s] = known->lost;
      continue;
    }
    unmeasured.push_back(s);
    for (const std::size_t k : near_primitives) near_unmeasured[k] = true;
  }
  if (unmeasured.empty()) return lost;

  // The primitives near the unmeasured stretches, each unbroken run of them as one pass
  // (a run's ends are shared poses, so the runs together see what the whole path sees
  // there).
  SeenArea smoothed(*raster_);
  for (std::size_t k = 0; k < primitives.size();) {
    if (!near_unmeasured[k]) {
      ++k;
      continue;
    }
    const std::size_t first = k;
    while (k < primitives.size() && near_unmeasured[k]) ++k;
    const std::vector<PathPrimitive> run(primitives.begin() + static_cast<std::ptrdiff_t>(first),
                                         primitives.begin() + static_cast<std::ptrdiff_t>(k));
    smoothed.addSweptPath(sweptPoses(run, raster_->cellSize(), reach_), sensor_);
  }
  for (const std::size_t s : unmeasured) {
    lost[s] = lostCellsIn(
        *raster_, cellWindow(*raster_, boxes[s]), reachable_, *sharp_, stretches[s], near,
        [&](int row, int column) { return smoothed.seen(raster_->index(row, column)); });
    measured_.push_back({stretches[s], std::move(nearby[s]), lost[s]});
  }
  return lost;
}

std::size_t PathCoverageCheck::lostCellsReplacing(std::size_t first_leg, std::size_t last_leg,
                                                  const std::vector<PathPrimitive>& replacement,
                                                  const ReplacedStretch& stretch) const {
  if (!raster_ || stretch.empty()) return 0;
  const double near = reach_ + raster_->cellSize();
  const Box box = nearBox(stretch, near);

  // A window of the raster around the stretch, its cells aligned with the raster's.
  const CellWindow cells = cellWindow(*raster_, box);
  if (cells.empty()) return 0;
  const double cell = raster_->cellSize();
  const CoverageRaster window(
      raster_->origin() + cell * Point2(cells.first_column, cells.first_row), cell,
      cells.last_column - cells.first_column + 1, cells.last_row - cells.first_row + 1);

  // What the path sees there with the replacement: the replacement, and every other sharp
  // leg and rotation that can see into the window, each its own pass.
  SeenArea seen(window);
  seen.addSweptPath(sweptPoses(replacement, cell, reach_), sensor_);
  const auto add = [&](const PathPrimitive& primitive) {
    if (grown(extentOf(primitive), near).intersects(box)) {
      seen.addSweptPath(sweptPoses({primitive}, cell, reach_), sensor_);
    }
  };
  for (std::size_t k = 0; k < legs_.size(); ++k) {
    if (k < first_leg || k > last_leg) add(legs_[k]);
  }
  for (std::size_t k = 0; k < rotations_.size(); ++k) {
    if (rotations_[k] && (k <= first_leg || k > last_leg)) add(*rotations_[k]);
  }

  return lostCellsIn(*raster_, cells, reachable_, *sharp_, stretch, near, [&](int row, int column) {
    return seen.seen(window.index(row - cells.first_row, column - cells.first_column));
  });
}

}  // namespace kinematic_coverage::core
