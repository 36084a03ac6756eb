#pragma once

#include <optional>
#include <string>

#include "coverage_system/parameters/planner_parameters.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// A point of the earth in WGS84 degrees.
struct GeoPoint {
  double latitude = 0.0;
  double longitude = 0.0;
};

/// A coverage mission as its file describes it (docs/REFERENCE.md, File formats): the raw area
/// (not yet validated or cleaned), where the robot starts and ends, and the parameters.
struct Mission {
  std::string frame_id = "map";  ///< frame of every coordinate, carried to every output
  PolygonWithHoles polygon;      ///< raw hull and holes, as in the file
  Point2 start = Point2::Zero();
  Point2 goal = Point2::Zero();
  PlannerParameters parameters;  ///< defaults, then the file's keys, then the overrides
  /// Set for a geo-referenced mission (a GeoJSON file): the origin of the local east-north
  /// frame (metres) its coordinates are in.
  std::optional<GeoPoint> datum;
};

}  // namespace kinematic_coverage::core
