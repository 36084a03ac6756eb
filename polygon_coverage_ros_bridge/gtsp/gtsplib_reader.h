#pragma once

#include <istream>
#include <string>

#include "polygon_coverage_ros_bridge/gtsp/gtsp_instance.h"

namespace kinematic_coverage::core {

/// A GTSPLIB problem: its name, TYPE (GTSP or AGTSP) and the cycle-mode instance with
/// integer costs (node i of the file is node i-1 of the instance).
struct GtsplibProblem {
  std::string name;
  std::string type;
  GtspInstance instance;
};

/// Reads GTSPLIB files (TSPLIB plus GTSP_SETS and GTSP_SET_SECTION; Fischetti, Salazar-
/// Gonzalez and Toth 1997): EDGE_WEIGHT_TYPE EUC_2D with TSPLIB rounding nint(d) =
/// floor(d + 0.5), or EXPLICIT with EDGE_WEIGHT_FORMAT FULL_MATRIX, UPPER_ROW, LOWER_ROW,
/// LOWER_DIAG_ROW or UPPER_DIAG_ROW. Tolerates the traps of the benchmark files: trailing
/// blanks, keywords without a colon, data wrapped over any number of lines. Malformed input
/// throws InvalidInputError naming the problem and its line.
class GtsplibReader {
 public:
  /// Parses a whole file's text; source names it in error messages.
  static GtsplibProblem parse(std::istream& in, const std::string& source);

  /// Opens and parses a file; a missing file is an InvalidInputError.
  static GtsplibProblem readFile(const std::string& path);
};

}  // namespace kinematic_coverage::core
