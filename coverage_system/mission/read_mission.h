#pragma once

#include <optional>
#include <string>
#include <vector>

#include "coverage_system/mission/mission.h"

namespace kinematic_coverage::core {

/// Reads a mission file of either format (docs/REFERENCE.md, File formats) by its
/// extension: a GeoJSON mission (GeoJsonMissionReader, anchored at `datum` when given) or
/// a YAML mission (MissionFileReader, which has no datum), over the parameters `base`, then
/// `overrides` ("name=value" each). The one way coverage_tool and the nodes open a mission.
Mission readMission(const std::string& path, const std::vector<std::string>& overrides = {},
                    const PlannerParameters& base = PlannerParameters{},
                    const std::optional<GeoPoint>& datum = std::nullopt);

}  // namespace kinematic_coverage::core
