#pragma once

#include <cstddef>
#include <vector>

#include "polygon_coverage_ros_bridge/decomposition/best_decomposition.h"
#include "polygon_coverage_ros_bridge/sweeps/sensor_options.h"

namespace kinematic_coverage::core {

/// Size limits of planning (docs/REFERENCE.md, Geometry and input rules: inputs over them
/// are invalid input), checked right after the decomposition, before anything of
/// their size is built: the memory the plan is estimated to need against max_memory_mb, and
/// the sweep lanes. The polygon's own limits (vertices, holes) are in
/// validation/polygon_validator.h. Measured in docs/RELIABILITY.md (Size limits).
/// At most this many sweep lanes over every cell and kept lane direction, counted from the
/// cells' widths across each direction over the sweep distance before any lane is placed.
constexpr std::size_t kMaxSweeps = 20000;

/// Nodes of the planner's generalized TSP: SweepPatternGenerator::kPatternsPerDirection
/// per kept lane direction of every cell, plus the start and the goal.
std::size_t gtspNodeCount(const std::vector<Decomposition>& decompositions);

/// What planMemoryEstimateBytes reads, known right after the decomposition, before the
/// visibility graph, the transitions and the generalized TSP allocate anything.
struct PlanSize {
  std::size_t cells = 0;
  std::size_t gtsp_nodes = 0;  ///< gtspNodeCount, after fitDirectionsToGtspLimit
  /// Corners of the route area where a route may bend (its rings' vertices at which the
  /// area's inside angle exceeds 180 degrees): about the visibility graph's nodes.
  std::size_t route_corners = 0;
  /// The visibility graph searches routes on demand instead of keeping all-pairs costs
  /// (PlanningOptions::dense_route_corners).
  bool routes_on_demand = false;
  /// Transitions are routed between nearby cells only (PlanningOptions::dense_transition_nodes).
  bool lazy_transitions = false;
};

/// The corners of `route_area` where a route may bend (PlanSize::route_corners).
std::size_t routeCorners(const PolygonWithHoles& route_area);

/// Bytes that the plan's largest structures take at once, estimated before they are built:
/// a baseline (kMemoryBaselineBytes: the process, the areas, the rasters of a map that the
/// project's benchmarks plan); the visibility graph's all-pairs costs and visibility flags
/// over its nodes V (8.5 V^2) and every sweep endpoint's cost to every node (8 n V), or on
/// demand its local edges (kOnDemandBytesPerCorner V); the transition costs and the
/// generalized TSP's dense matrix with the transitions' working copy (24 n^2, n nodes), or
/// with lazy transitions the matrix alone (8 n^2); and the local searches' cluster distances
/// (24 m^2, m cells).
double planMemoryEstimateBytes(const PlanSize& size);

/// Bytes per route corner of a visibility graph searched on demand: its local edges and
/// the nodes that the sweep endpoints see.
constexpr double kOnDemandBytesPerCorner = 4096.0;

/// Bytes of a plan beyond its quadratic structures (planMemoryEstimateBytes).
constexpr double kMemoryBaselineBytes = 48.0 * 1024.0 * 1024.0;

/// max_memory_mb's meaning of 0 (its default): half the machine's physical memory, in MB.
double machineMaxMemoryMb();

/// planMemoryEstimateBytes(size) in MB; throws SizeLimitError when it exceeds `max_memory_mb`,
/// with the estimate, the figures behind it and what reduces them.
double checkMemoryEstimate(const PlanSize& size, double max_memory_mb, DecompositionType type);

/// Keeps the cells' best lane directions so that gtspNodeCount stays within kMaxGtspNodes:
/// every cell's best direction, then every cell's second best while they fit, and so on
/// (every best direction is kept, however many nodes that takes: the memory estimate
/// decides whether the plan can be made). Returns how many directions were dropped.
std::size_t fitDirectionsToGtspLimit(std::vector<Decomposition>& decompositions);

/// The fewest sweep lanes the kept directions can take: per cell and direction, the cell's
/// width across the direction over the sweep distance (SweepPatternGenerator places lanes
/// at most a sweep distance apart), at least one. A double: it may exceed any integer type.
double minimumLaneCount(const std::vector<Decomposition>& decompositions, double sweep_distance);

/// Throws InvalidInputError when minimumLaneCount exceeds kMaxSweeps, saying by how much and
/// which parameters widen the sweep distance.
void checkLaneLimit(const std::vector<Decomposition>& decompositions, const SensorOptions& sensor);

}  // namespace kinematic_coverage::core
