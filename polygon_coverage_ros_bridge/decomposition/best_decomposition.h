#pragma once

#include <cstddef>
#include <vector>

#include "polygon_coverage_ros_bridge/decomposition/sweep_line_decomposition.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// A cell and the lane directions that sweep it without leaving it.
struct Cell {
  Ring polygon;                          ///< counter-clockwise
  std::vector<double> sweep_directions;  ///< best (smallest altitude) first
  double altitude = 0.0;                 ///< across the best direction
};

/// The chosen decomposition of an area.
struct Decomposition {
  std::vector<Cell> cells;
  double direction = 0.0;       ///< the sweep-line direction that produced it
  double total_altitude = 0.0;  ///< the sum of the cells' altitudes
  std::size_t directions_tried = 0;
};

/// Bounds of the search over directions.
struct DecompositionOptions {
  /// Candidate directions for the whole area (edge directions with the most length).
  std::size_t max_directions = 32;
  /// Lane directions kept per cell: its own edge directions along which it is monotone,
  /// with an altitude within `altitude_slack` times the best one.
  std::size_t max_cell_directions = 4;
  double altitude_slack = 1.5;
  /// Where boustrophedon cells end.
  CellJoining joining = CellJoining::kAtCriticalPoints;
};

/// Decomposes the area for every candidate direction and keeps the decomposition with
/// the smallest total altitude, each cell counted with the altitude of its best lane
/// direction among its own edges (Thesis 3.1 / its reference [10]).
Decomposition computeBestDecomposition(const PolygonWithHoles& area, DecompositionType type,
                                       const DecompositionOptions& options = {});

}  // namespace kinematic_coverage::core
