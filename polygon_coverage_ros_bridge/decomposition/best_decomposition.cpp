#include "polygon_coverage_ros_bridge/decomposition/best_decomposition.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "polygon_coverage_ros_bridge/base/parallel_for.h"
#include "polygon_coverage_ros_bridge/decomposition/sweep_direction.h"

namespace kinematic_coverage::core {
namespace {

/// The lane directions of a cell: the decomposition's own direction (always valid) and
/// the cell's edge directions along which it is monotone, best first.
Cell makeCell(Ring polygon, double decomposition_direction, const DecompositionOptions& options) {
  std::vector<double> candidates = candidateDirections({polygon}, polygon.size());
  candidates.push_back(decomposition_direction);
  std::vector<std::pair<double, double>> valid;  // (altitude, direction)
  for (double direction : candidates) {
    const bool duplicate = std::any_of(valid.begin(), valid.end(), [&](const auto& v) {
      const double difference = std::abs(std::remainder(v.second - direction, M_PI));
      return difference <= kDirectionTolerance;
    });
    if (duplicate) continue;
    if (direction != decomposition_direction && !isMonotone(polygon, direction)) continue;
    valid.emplace_back(altitude(polygon, direction), direction);
  }
  std::stable_sort(valid.begin(), valid.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  Cell cell;
  cell.polygon = std::move(polygon);
  cell.altitude = valid.front().first;
  for (const auto& [cell_altitude, direction] : valid) {
    if (cell.sweep_directions.size() >= options.max_cell_directions) break;
    if (cell_altitude > options.altitude_slack * cell.altitude + 1e-12) break;
    cell.sweep_directions.push_back(direction);
  }
  return cell;
}

}  // namespace

Decomposition computeBestDecomposition(const PolygonWithHoles& area, DecompositionType type,
                                       const DecompositionOptions& options) {
  std::vector<Ring> rings = {area.hull};
  rings.insert(rings.end(), area.holes.begin(), area.holes.end());
  const std::vector<double> directions = candidateDirections(rings, options.max_directions);
  const SweepLineDecomposition decomposition(type, options.joining);
  // The directions on every hardware thread; the first of least total altitude wins, and a
  // failure is the first direction's in order, as one loop would have it.
  std::vector<Decomposition> candidates(directions.size());
  parallelForInOrder(directions.size(), [&](std::size_t k) {
    Decomposition& candidate = candidates[k];
    candidate.direction = directions[k];
    for (Ring& polygon : decomposition.decompose(area, directions[k])) {
      candidate.cells.push_back(makeCell(std::move(polygon), directions[k], options));
      candidate.total_altitude += candidate.cells.back().altitude;
    }
  });
  Decomposition best;
  best.total_altitude = std::numeric_limits<double>::infinity();
  for (Decomposition& candidate : candidates) {
    if (candidate.total_altitude < best.total_altitude) best = std::move(candidate);
  }
  best.directions_tried = directions.size();
  return best;
}

}  // namespace kinematic_coverage::core
