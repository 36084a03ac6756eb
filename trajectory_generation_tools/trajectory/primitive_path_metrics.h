#pragma once

#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/path/path_primitive.h"

namespace kinematic_coverage::core {

/// `trajectory_length_m` (docs/REFERENCE.md, Metrics): the sum of the primitives' exact lengths
/// (rotations add nothing).
double primitivePathLength(const std::vector<PathPrimitive>& path);

/// `max_curvature`: the largest curvature over the segments (0) and arcs (1 / r); 0 for a
/// path with neither. Rotations, with no finite curvature, are left out.
double primitivePathMaxCurvature(const std::vector<PathPrimitive>& path);

/// Where a path comes nearest the hull and holes.
struct ClosestApproach {
  double distance_m = 0.0;        ///< primitivePathClearance
  Point2 point = Point2::Zero();  ///< a point of the path that distance away (within 1 cm)
};

/// primitivePathClearance and a point of the path where it is reached (the nearest of the
/// nearest primitive's points 1 cm apart); the point is the origin when the distance is
/// infinite.
ClosestApproach primitivePathClosestApproach(const std::vector<PathPrimitive>& path,
                                             const PolygonWithHoles& free_area);

/// `min_obstacle_clearance_m`: the smallest distance from the path's points (segments and
/// arcs exactly, rotations at their position) to the boundary of `free_area` (the raw
/// hull and holes, docs/REFERENCE.md, Metrics); 0 where the path touches or crosses it.
/// Infinity for an empty path or an area with no edges (the metric is then meaningless).
double primitivePathClearance(const std::vector<PathPrimitive>& path,
                              const PolygonWithHoles& free_area);

}  // namespace kinematic_coverage::core
