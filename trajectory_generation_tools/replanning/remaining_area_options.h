#pragma once

#include "polygon_coverage_ros_bridge/sweeps/sensor_options.h"

namespace kinematic_coverage::core {

/// How the area the robot has seen is taken from its visited poses (`replanning_method`,
/// thesis Fig. 3.9).
enum class ReplanningMethod {
  kConvexHull,   ///< the convex hull of every footprint corner
  kConcaveHull,  ///< the alpha shape of the footprint corners
  kFootprint,    ///< the footprints themselves
};

/// The options the remaining area reads (docs/REFERENCE.md, Parameters).
struct RemainingAreaOptions {
  ReplanningMethod method = ReplanningMethod::kFootprint;
  SensorOptions sensor;             ///< whose footprints the visited poses saw
  double sliver_fraction = 0.2;     ///< parts narrower than this x sweep spacing go
  double min_area = 1.0;            ///< m^2, smaller parts go
  double simplify_tolerance = 0.1;  ///< m, boundary simplification
  double alpha = 2.0;               ///< m, the alpha shape's parameter (kConcaveHull)
};

}  // namespace kinematic_coverage::core
