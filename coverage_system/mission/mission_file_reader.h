#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "coverage_system/mission/mission.h"

namespace kinematic_coverage::core {

/// Reads mission files (docs/REFERENCE.md, File formats) with yaml-cpp:
///
///     frame_id: map
///     polygon:
///       hull: [[0, 0], [30, 0], [30, 30], [0, 30]]
///       holes: [[[8, 8], [12, 8], [12, 12], [8, 12]]]
///     start: [1, 1]
///     goal: [29, 29]
///     turning_radius: 1.0      # any parameter of docs/REFERENCE.md, Parameters
///
/// Values: the built-in defaults (PlannerParameters) or a parameter file's, then the file's
/// keys, then `--set name=value` overrides (the value read as a YAML scalar). Every problem is an
/// InvalidInputError naming where it is, e.g. "lake.yaml:7: polygon.holes[1][3]: the x
/// coordinate 'abc' is not a number": unknown keys (a typo must not be silently
/// ignored), duplicate keys, wrong shapes, non-numeric or non-finite numbers, parameters
/// out of range (checkParameters, naming where the value came from). Points are `[x, y]`; holes and
/// vertices are numbered from 0. Limits: files of at most kMaxMissionFileBytes; at most
/// kMaxTotalVertices vertices and kMaxHoles holes (polygon_validator.h); coordinates within
/// +-kMaxCoordinateMagnitude. Geometry (simplicity, holes outside the hull, ...) is left to
/// PolygonValidator.
class MissionFileReader {
 public:
  /// Largest mission or polygon file read, bytes.
  static constexpr std::size_t kMaxMissionFileBytes = 64u << 20;

  /// Reads the mission file at `path` over the parameters `base`, then applies `overrides`
  /// ("name=value" each). `polygon`, `start` and `goal` are required; `frame_id` and
  /// parameters optional.
  Mission read(const std::string& path, const std::vector<std::string>& overrides = {},
               const PlannerParameters& base = PlannerParameters{}) const;

  /// As read(), from YAML text; `source_name` names it in messages.
  Mission parse(const std::string& yaml_text, const std::string& source_name,
                const std::vector<std::string>& overrides = {},
                const PlannerParameters& base = PlannerParameters{}) const;

  /// Reads an UPDATED.yaml of replanning: a `polygon:` (and optionally `frame_id:`) only.
  PolygonWithHoles readUpdatedPolygon(const std::string& path) const;

  /// As readUpdatedPolygon(), from YAML text.
  PolygonWithHoles parseUpdatedPolygon(const std::string& yaml_text,
                                       const std::string& source_name) const;

  /// Reads a file of parameter keys only (config/default.yaml) over the built-in defaults.
  PlannerParameters readParameters(const std::string& path) const;

  /// `parameters` with `overrides` ("name=value" each, the value read as YAML) applied,
  /// then validated: how the nodes apply their private parameters.
  PlannerParameters withOverrides(PlannerParameters parameters,
                                  const std::vector<std::string>& overrides) const;

  /// The text of the file at `path`. Throws InvalidInputError naming the path when it does
  /// not exist, is not a regular file, is larger than kMaxMissionFileBytes or cannot be read.
  static std::string readText(const std::string& path);

  /// The names of every parameter a mission file or `--set` may give.
  static std::vector<std::string> parameterNames();

  /// The value of the parameter `name` in `parameters` as a mission file writes it ("0.5",
  /// "true", "boustrophedon"; numbers in the shortest form that reads back exactly), e.g. to
  /// compare, print or export parameter sets. Throws
  /// InvalidInputError for an unknown name.
  static std::string parameterText(const PlannerParameters& parameters, const std::string& name);
};

}  // namespace kinematic_coverage::core
