#include "polygon_coverage_ros_bridge/validation/free_area_builder.h"

#include <algorithm>
#include <chrono>
#include <sstream>

#include "polygon_coverage_ros_bridge/base/elapsed_seconds.h"
#include "polygon_coverage_ros_bridge/geometry/boundary_simplification.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/validation/polygon_validator.h"

namespace kinematic_coverage::core {
namespace {

/// True when an endpoint lies in a hole of `simplified` but not in that hole of `free_area`
/// (the simplification grew the hole over it): planning would then blame the user's point.
bool swallowsAnEndpoint(const PolygonWithHoles& free_area, const PolygonWithHoles& simplified,
                        const std::vector<NamedEndpoint>& endpoints) {
  for (const auto& [name, point] : endpoints) {
    for (std::size_t i = 0; i < simplified.holes.size(); ++i) {
      if (insideRing(point, simplified.holes[i]) && !insideRing(point, free_area.holes[i])) {
        return true;
      }
    }
  }
  return false;
}

/// The most vertices of a ring of the area.
std::size_t largestRing(const PolygonWithHoles& area) {
  std::size_t largest = area.hull.size();
  for (const Ring& hole : area.holes) largest = std::max(largest, hole.size());
  return largest;
}

/// The cleaned free area simplified inward within `tolerance` where a ring has more than
/// kMaxExactRingVertices vertices, with a warning; unchanged otherwise.
void fitToTheExactLimit(double tolerance, const std::vector<NamedEndpoint>& endpoints,
                        CleanedPolygon* cleaned) {
  const PolygonWithHoles& free_area = cleaned->free_area;
  if (tolerance <= 0.0 || largestRing(free_area) <= kMaxExactRingVertices) return;
  PolygonWithHoles simplified = BoundarySimplification(tolerance).simplify(free_area);
  if (swallowsAnEndpoint(free_area, simplified, endpoints)) return;
  std::ostringstream warning;
  warning << "the free area has a ring of " << largestRing(free_area) << " vertices, more than the "
          << kMaxExactRingVertices << " planned as they are: simplified inward within " << tolerance
          << " m (boundary_simplification), " << BoundarySimplification::vertexCount(free_area)
          << " -> " << BoundarySimplification::vertexCount(simplified) << " vertices, "
          << area(free_area) - area(simplified)
          << " m^2 along the boundary given up as wall (neither planned nor counted)";
  cleaned->warnings.push_back(warning.str());
  cleaned->free_area = std::move(simplified);
}

}  // namespace

BuiltFreeArea FreeAreaBuilder::build(const PolygonWithHoles& raw,
                                     const std::vector<NamedEndpoint>& endpoints) const {
  BuiltFreeArea built;
  auto start = std::chrono::steady_clock::now();
  const PolygonValidator validator;
  validator.validate(raw);
  for (const auto& [name, point] : endpoints) validator.validateEndpoint(name, point, raw);
  built.validate_s = secondsSince(start);

  start = std::chrono::steady_clock::now();
  built.cleaned = PolygonCleaner().clean(raw);
  fitToTheExactLimit(simplification_, endpoints, &built.cleaned);
  built.clean_s = secondsSince(start);
  return built;
}

}  // namespace kinematic_coverage::core
