// libFuzzer target: mission YAML loading (MissionFileReader::parse, parseUpdatedPolygon) on
// arbitrary text, then what planMission does before planning: PolygonValidator on the
// polygon, start and goal, and PolygonCleaner. Properties: the parameters of a parsed
// mission pass checkParameters; the cleaned free area has a counter-clockwise simple
// hull, clockwise simple holes and a positive area no larger than the raw hull's
// (docs/REFERENCE.md, Geometry and input rules).

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "coverage_system/mission/mission_file_reader.h"
#include "coverage_system/parameters/parameter_schema.h"
#include "fuzz/fuzz_check.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/validation/polygon_cleaner.h"
#include "polygon_coverage_ros_bridge/validation/polygon_validator.h"

namespace {

using kinematic_coverage::core::CleanedPolygon;
using kinematic_coverage::core::InvalidInputError;
using kinematic_coverage::core::Mission;
using kinematic_coverage::core::MissionFileReader;
using kinematic_coverage::core::PolygonCleaner;
using kinematic_coverage::core::PolygonValidator;
using kinematic_coverage::core::PolygonWithHoles;
using kinematic_coverage::core::Ring;
using kinematic_coverage::fuzz::fuzzCheck;

/// Checks the cleaner's output against docs/REFERENCE.md, Geometry and input rules.
void checkCleaned(const PolygonWithHoles& raw, const CleanedPolygon& cleaned) {
  const PolygonWithHoles& free_area = cleaned.free_area;
  const PolygonValidator validator;
  try {
    validator.validateRing(free_area.hull, "cleaned hull");
    for (const Ring& hole : free_area.holes) validator.validateRing(hole, "cleaned hole");
  } catch (const InvalidInputError& error) {
    fuzzCheck(false, std::string("cleaner produced a bad ring: ") + error.what());
  }
  fuzzCheck(kinematic_coverage::core::signedArea(free_area.hull) > 0.0,
            "cleaned hull is not counter-clockwise");
  for (const Ring& hole : free_area.holes) {
    fuzzCheck(kinematic_coverage::core::signedArea(hole) < 0.0, "cleaned hole is not clockwise");
  }
  const double free = kinematic_coverage::core::area(free_area);
  const double hull = std::abs(kinematic_coverage::core::signedArea(raw.hull));
  fuzzCheck(free > 0.0, "cleaned free area is empty but no error was raised");
  fuzzCheck(free <= hull * (1.0 + 1e-9), "cleaned free area " + std::to_string(free) +
                                             " exceeds the raw hull's " + std::to_string(hull));
}

/// planMission's steps before planning.
void validateAndClean(const Mission& mission) {
  try {
    kinematic_coverage::core::checkParameters(mission.parameters);
  } catch (const InvalidInputError& error) {
    fuzzCheck(false, std::string("reader accepted invalid parameters: ") + error.what());
  }
  const PolygonValidator validator;
  validator.validate(mission.polygon);
  validator.validateEndpoint("start", mission.start, mission.polygon);
  validator.validateEndpoint("goal", mission.goal, mission.polygon);
  checkCleaned(mission.polygon, PolygonCleaner().clean(mission.polygon));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const MissionFileReader reader;
  kinematic_coverage::fuzz::runExpectingOnlyInvalidInput(
      [&] { validateAndClean(reader.parse(text, "fuzz.yaml")); });
  kinematic_coverage::fuzz::runExpectingOnlyInvalidInput([&] {
    const PolygonWithHoles polygon = reader.parseUpdatedPolygon(text, "fuzz.yaml");
    PolygonValidator().validate(polygon);
    checkCleaned(polygon, PolygonCleaner().clean(polygon));
  });
  return 0;
}
