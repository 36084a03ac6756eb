#pragma once

#include <chrono>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "coverage_system/mission/mission.h"

namespace kinematic_coverage::core {

/// The arguments of a coverage_tool command on a mission (docs/REFERENCE.md, coverage_tool): one
/// mission file, options that take a value (`--out DIR`, ...), an optional parameter file
/// (`--config FILE`), `--set name=value` overrides in command-line order, and `--help`.
struct CommandArguments {
  std::string mission_path;
  /// Each option's value by the option's name, e.g. "--out" -> "DIR".
  std::map<std::string, std::string> values;
  /// "name=value" of every `--set`, in order.
  std::vector<std::string> overrides;
  /// `--config FILE`: a parameter file (as config/default.yaml or config/thesis.yaml) read
  /// over the built-in defaults and under the mission file; empty when not given.
  std::string config_path;
  bool help = false;
};

/// An option that takes a value, e.g. `--out DIR`.
struct CommandOption {
  std::string name;      ///< "--out"
  std::string value;     ///< how the usage text names its value: "DIR"
  bool required = true;  ///< false: it may be left out
};

/// Parses the arguments after the command's name `command` ("plan", "evaluate"): the
/// command's `options`, `--config`, `--set` and `--help` in any order around one mission file.
/// Throws InvalidInputError naming the problem: an option without its value, an unknown option, no
/// mission file or two, or, unless `--help` is given, a required option missing or empty.
CommandArguments parseCommandArguments(const std::string& command,
                                       const std::vector<std::string>& args,
                                       const std::vector<CommandOption>& options);

/// Reads the mission file of `arguments` over its parameter file, with its overrides
/// (MissionFileReader), and prints the "load: ..." progress line to `out`. Throws
/// InvalidInputError as the reader.
Mission loadMission(const CommandArguments& arguments, std::ostream& out);

/// What a command on a mission file starts from: its arguments and its mission.
struct MissionCommandInput {
  CommandArguments arguments;
  Mission mission;
};

/// The common start of the commands on a mission file: parses `args` (parseCommandArguments)
/// and loads the mission (loadMission, its "load: ..." line on `out`); with `--help`, prints
/// `usage` to `out` and returns none. Throws InvalidInputError as those.
std::optional<MissionCommandInput> startMissionCommand(const std::string& command,
                                                       const std::vector<std::string>& args,
                                                       const std::vector<CommandOption>& options,
                                                       const std::string& usage, std::ostream& out);

/// "LAT,LON" in degrees (the value of `--datum`) as a datum; InvalidInputError naming the
/// text otherwise, or a latitude or longitude out of range.
GeoPoint parseDatum(const std::string& text);

/// Creates the output directory `dir` and its parents; InvalidInputError when it cannot.
void createOutputDirectory(const std::string& dir);

}  // namespace kinematic_coverage::core
