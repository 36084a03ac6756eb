#pragma once

#include <string>
#include <utility>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "polygon_coverage_ros_bridge/validation/polygon_cleaner.h"

namespace kinematic_coverage::core {

/// A free area built from user input, and how long each step took (for the stage lines).
struct BuiltFreeArea {
  CleanedPolygon cleaned;   ///< the free area and one warning per cleaning step
  double validate_s = 0.0;  ///< checking the polygon and the endpoints
  double clean_s = 0.0;     ///< cleaning the polygon
};

/// A point the input names, checked against the raw polygon: ("start", p) or ("goal", p).
using NamedEndpoint = std::pair<std::string, Point2>;

/// The one way every entry point (planning, replanning, evaluation, simulation, the
/// trajectory node) turns a user's polygon into the free area the stages work in
/// (docs/REFERENCE.md, Geometry and input rules): validate the raw polygon and its
/// endpoints (PolygonValidator), then clean it (PolygonCleaner), so no stage ever sees a
/// polygon that skipped either step.
class FreeAreaBuilder {
 public:
  /// Throws InvalidInputError for an invalid polygon, an endpoint inside a hole or not
  /// finite, or holes that cover the hull or split the free area.
  BuiltFreeArea build(const PolygonWithHoles& raw,
                      const std::vector<NamedEndpoint>& endpoints = {}) const;
};

}  // namespace kinematic_coverage::core
