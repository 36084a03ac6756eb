#include "coverage_system/planner/planning_limits.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "polygon_coverage_ros_bridge/decomposition/sweep_direction.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/gtsp/gtsp_instance.h"
#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"
#include "polygon_coverage_ros_bridge/sweeps/sweep_pattern.h"

namespace kinematic_coverage::core {
namespace {

/// Generalized TSP nodes per kept lane direction of a cell, and for the start and goal.
constexpr std::size_t kNodesPerDirection = SweepPatternGenerator::kPatternsPerDirection;
constexpr std::size_t kTerminalNodes = 2;

}  // namespace

std::size_t gtspNodeCount(const std::vector<Decomposition>& decompositions) {
  std::size_t nodes = kTerminalNodes;
  for (const Decomposition& decomposition : decompositions) {
    for (const Cell& cell : decomposition.cells) {
      nodes += kNodesPerDirection * cell.sweep_directions.size();
    }
  }
  return nodes;
}

std::size_t routeCorners(const PolygonWithHoles& route_area) {
  std::size_t corners = 0;
  auto count = [&corners](const Ring& ring, bool inside_left) {
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      const double turn = cross(ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]);
      if (inside_left ? turn < 0.0 : turn > 0.0) ++corners;
    }
  };
  // The inside lies left of a counter-clockwise hull and right of a counter-clockwise hole.
  count(route_area.hull, signedArea(route_area.hull) > 0.0);
  for (const Ring& hole : route_area.holes) count(hole, signedArea(hole) < 0.0);
  return corners;
}

double planMemoryEstimateBytes(const PlanSize& size) {
  const double v = static_cast<double>(size.route_corners);
  const double n = static_cast<double>(size.gtsp_nodes);
  const double m = static_cast<double>(size.cells);
  const double graph =
      size.routes_on_demand ? kOnDemandBytesPerCorner * v : 8.5 * v * v + 8.0 * n * v;
  const double transitions = (size.lazy_transitions ? 8.0 : 24.0) * n * n;
  return kMemoryBaselineBytes + graph + transitions + 24.0 * m * m;
}

double machineMaxMemoryMb() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return 4096.0;  // unknown: a small machine's half
  return 0.5 * static_cast<double>(pages) * static_cast<double>(page_size) / (1024.0 * 1024.0);
}

double checkMemoryEstimate(const PlanSize& size, double max_memory_mb, DecompositionType type) {
  const double estimate_mb = planMemoryEstimateBytes(size) / (1024.0 * 1024.0);
  if (estimate_mb <= max_memory_mb) return estimate_mb;
  std::ostringstream message;
  message << std::fixed << std::setprecision(0) << "the plan would need about " << estimate_mb
          << " MB, more than max_memory_mb " << max_memory_mb << " MB (" << size.cells
          << " cells with " << size.gtsp_nodes << " generalized TSP nodes, whose transition "
          << "costs grow with their square, and a route area of " << size.route_corners
          << " corners, whose visibility graph grows with theirs): simplify the polygon (every "
             "hole, and every boundary vertex where the boundary turns back across the sweep, "
             "adds cells: merge or drop small holes, smooth the boundary), use a larger "
             "wall_distance (it closes narrow gaps and rounds off small bumps) or "
             "boundary_simplification, plan the area in parts, or raise max_memory_mb where the "
             "machine has the memory";
  if (type == DecompositionType::kTrapezoidal) {
    message << "; the boustrophedon decomposition makes fewer cells than the trapezoidal one";
  }
  throw SizeLimitError(message.str());
}

std::size_t fitDirectionsToGtspLimit(std::vector<Decomposition>& decompositions) {
  if (gtspNodeCount(decompositions) <= static_cast<std::size_t>(kMaxGtspNodes)) return 0;
  std::size_t most_directions = 0;
  std::vector<std::size_t> kept;  // per cell, in order over the decompositions
  std::size_t nodes = kTerminalNodes;
  for (const Decomposition& decomposition : decompositions) {
    for (const Cell& cell : decomposition.cells) {
      most_directions = std::max(most_directions, cell.sweep_directions.size());
      const std::size_t best = std::min<std::size_t>(1, cell.sweep_directions.size());
      kept.push_back(best);
      nodes += kNodesPerDirection * best;
    }
  }
  for (std::size_t rank = 1; rank < most_directions; ++rank) {
    std::size_t k = 0;
    for (const Decomposition& decomposition : decompositions) {
      for (const Cell& cell : decomposition.cells) {
        if (cell.sweep_directions.size() > rank &&
            nodes + kNodesPerDirection <= static_cast<std::size_t>(kMaxGtspNodes)) {
          nodes += kNodesPerDirection;
          kept[k] = rank + 1;
        }
        ++k;
      }
    }
  }
  std::size_t dropped = 0;
  std::size_t k = 0;
  for (Decomposition& decomposition : decompositions) {
    for (Cell& cell : decomposition.cells) {
      dropped += cell.sweep_directions.size() - kept[k];
      cell.sweep_directions.resize(kept[k++]);
    }
  }
  return dropped;
}

double minimumLaneCount(const std::vector<Decomposition>& decompositions, double sweep_distance) {
  double lanes = 0.0;
  for (const Decomposition& decomposition : decompositions) {
    for (const Cell& cell : decomposition.cells) {
      for (double direction : cell.sweep_directions) {
        lanes += std::max(1.0, std::floor(altitude(cell.polygon, direction) / sweep_distance));
      }
    }
  }
  return lanes;
}

void checkLaneLimit(const std::vector<Decomposition>& decompositions, const SensorOptions& sensor) {
  const double spacing = FrustumSensor::fromOptions(sensor).sweepDistance();
  const double lanes = minimumLaneCount(decompositions, spacing);
  const double limit = static_cast<double>(kMaxSweeps);
  if (lanes <= limit) return;
  std::ostringstream message;
  message << std::fixed << std::setprecision(0) << "the cells need at least " << lanes
          << " sweep lanes, " << lanes - limit << " more than the limit of " << limit
          << std::defaultfloat << std::setprecision(3)
          << " (their widths across the lanes over the sweep distance of " << spacing
          << " m, which is (1 - lateral_overlap) x the footprint width): the sweep distance must "
             "grow about "
          << lanes / limit << " times: ";
  if (sensor.model == SensorModel::kLine) {
    message << "a larger lateral_footprint";
  } else {
    message << "a larger sensor_distance (the sensor's height above the bottom) or lateral_fov";
  }
  message << ", or a smaller lateral_overlap; or plan a smaller area";
  throw SizeLimitError(message.str());
}

}  // namespace kinematic_coverage::core
