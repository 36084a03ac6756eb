#include "polygon_coverage_ros_bridge/validation/free_area_builder.h"

#include <chrono>

#include "polygon_coverage_ros_bridge/base/elapsed_seconds.h"
#include "polygon_coverage_ros_bridge/validation/polygon_validator.h"

namespace kinematic_coverage::core {

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
  built.clean_s = secondsSince(start);
  return built;
}

}  // namespace kinematic_coverage::core
