#pragma once

#include <cstddef>
#include <vector>

#include "polygon_coverage_ros_bridge/decomposition/best_decomposition.h"
#include "polygon_coverage_ros_bridge/sweeps/sensor_options.h"

namespace kinematic_coverage::core {

/// Size limits of planning (docs/REFERENCE.md, Geometry and input rules: inputs over them
/// are invalid input), checked right after the decomposition, before anything of
/// their size is built. The polygon's own limits (vertices, holes) are in
/// validation/polygon_validator.h, the generalized TSP's (kMaxGtspNodes) in
/// gtsp/gtsp_instance.h. Measured in docs/RELIABILITY.md (Memory bound).
/// At most this many cells in the chosen decomposition: every cell is a cluster of the
/// generalized TSP, whose solving time grows faster than the cell count.
constexpr std::size_t kMaxCells = 1000;
/// At most this many sweep lanes over every cell and kept lane direction, counted from the
/// cells' widths across each direction over the sweep distance before any lane is placed.
constexpr std::size_t kMaxSweeps = 20000;

/// Nodes of the planner's generalized TSP: SweepPatternGenerator::kPatternsPerDirection
/// per kept lane direction of every cell, plus the start and the goal.
std::size_t gtspNodeCount(const std::vector<Decomposition>& decompositions);

/// Throws InvalidInputError when the decompositions have more than kMaxCells cells in all,
/// saying by how many and what reduces them.
void checkCellLimit(const std::vector<Decomposition>& decompositions, DecompositionType type);

/// Keeps the cells' best lane directions so that gtspNodeCount stays within kMaxGtspNodes:
/// every cell's best direction, then every cell's second best while they fit, and so on
/// (with at most kMaxCells cells, every best direction fits). Returns how many directions
/// were dropped.
std::size_t fitDirectionsToGtspLimit(std::vector<Decomposition>& decompositions);

/// The fewest sweep lanes the kept directions can take: per cell and direction, the cell's
/// width across the direction over the sweep distance (SweepPatternGenerator places lanes
/// at most a sweep distance apart), at least one. A double: it may exceed any integer type.
double minimumLaneCount(const std::vector<Decomposition>& decompositions, double sweep_distance);

/// Throws InvalidInputError when minimumLaneCount exceeds kMaxSweeps, saying by how much and
/// which parameters widen the sweep distance.
void checkLaneLimit(const std::vector<Decomposition>& decompositions, const SensorOptions& sensor);

}  // namespace kinematic_coverage::core
