#pragma once

#include <cstddef>
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

/// Most vertices of one ring (the hull or a hole) of a free area planned as it is. The route
/// area's visibility graph, the cells and the transitions grow with a noisy boundary's
/// vertices: planned exactly, the 5 000-vertex lake chart of scaling_benchmark takes 4.5 s
/// (195 cells), the 10 000-vertex one 19 s (483 cells, 573 MB), within the goal of 30 s and
/// 2 GB for such charts (docs/BENCHMARKS.md).
constexpr std::size_t kMaxExactRingVertices = 10000;

/// A point the input names, checked against the raw polygon: ("start", p) or ("goal", p).
using NamedEndpoint = std::pair<std::string, Point2>;

/// The one way every entry point (planning, replanning, evaluation, simulation, the
/// trajectory node) turns a user's polygon into the free area the stages work in
/// (docs/REFERENCE.md, Geometry and input rules): validate the raw polygon and its
/// endpoints (PolygonValidator), then clean it (PolygonCleaner), so no stage ever sees a
/// polygon that skipped either step. A free area with a ring of more than
/// kMaxExactRingVertices vertices (a chart of thousands of noisy vertices) is simplified
/// inward within `simplification` (BoundarySimplification), with a warning naming the area
/// given up; the rest of the pipeline then works in that area (what lies beyond it is
/// treated as wall).
class FreeAreaBuilder {
 public:
  /// `simplification` (m, >= 0): how far the boundary of a free area with a ring of more
  /// than kMaxExactRingVertices vertices may move inward; 0: never.
  explicit FreeAreaBuilder(double simplification = 0.0) : simplification_(simplification) {}

  /// Throws InvalidInputError for an invalid polygon, an endpoint inside a hole or not
  /// finite, or holes that cover the hull or split the free area.
  BuiltFreeArea build(const PolygonWithHoles& raw,
                      const std::vector<NamedEndpoint>& endpoints = {}) const;

 private:
  double simplification_;
};

}  // namespace kinematic_coverage::core
