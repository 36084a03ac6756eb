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
/// polygon that skipped either step. A free area whose wall offset would exceed the straight
/// skeleton's limit (kMaxSkeletonPairs: a chart of thousands of noisy vertices) is
/// simplified inward within `skeleton_simplification` (BoundarySimplification), with a
/// warning naming the area given up, so that it is planned instead of refused; the rest of
/// the pipeline then works in that area (what lies beyond it is treated as wall).
class FreeAreaBuilder {
 public:
  /// `skeleton_simplification` (m, >= 0): how far the boundary of a free area too large for
  /// the wall offset may move inward; 0: never (the offset refuses such an area).
  explicit FreeAreaBuilder(double skeleton_simplification = 0.0)
      : skeleton_simplification_(skeleton_simplification) {}

  /// Throws InvalidInputError for an invalid polygon, an endpoint inside a hole or not
  /// finite, or holes that cover the hull or split the free area.
  BuiltFreeArea build(const PolygonWithHoles& raw,
                      const std::vector<NamedEndpoint>& endpoints = {}) const;

 private:
  double skeleton_simplification_;
};

}  // namespace kinematic_coverage::core
