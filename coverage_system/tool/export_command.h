#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace kinematic_coverage::core {

/// `coverage_tool export MISSION.yaml --datum LAT,LON --out FILE.geojson [--config FILE]
/// [--set name=value ...]`: the mission's area, start and goal as a geo-referenced GeoJSON
/// mission (GeoJsonWriter::mission), its metres taken as east and north of the datum, the
/// datum written as the polygon feature's `datum`; `coverage_tool plan FILE.geojson` plans it
/// as it plans the mission file.
class ExportCommand {
 public:
  /// Usage text of the command.
  static std::string usage();

  /// Runs the command on its arguments (those after "export"). Throws InvalidInputError for
  /// invalid input: a bad datum, a mission the reader rejects, a point too far from the
  /// datum for a local frame, a file that cannot be written.
  void run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) const;
};

}  // namespace kinematic_coverage::core
