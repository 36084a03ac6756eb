#include "coverage_system/tool/command_line.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <system_error>

#include "coverage_system/mission/mission_file_reader.h"
#include "coverage_system/mission/read_mission.h"
#include "polygon_coverage_ros_bridge/base/elapsed_seconds.h"
#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {

CommandArguments parseCommandArguments(const std::string& command,
                                       const std::vector<std::string>& args,
                                       const std::vector<CommandOption>& options) {
  const std::string prefix = "coverage_tool " + command + ": ";
  const auto is_option = [&](const std::string& arg) {
    return std::any_of(options.begin(), options.end(),
                       [&](const CommandOption& option) { return option.name == arg; });
  };
  CommandArguments parsed;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    const auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw InvalidInputError(prefix + arg + " needs a value");
      return args[++i];
    };
    if (arg == "--help" || arg == "-h") {
      parsed.help = true;
    } else if (arg == "--set") {
      parsed.overrides.push_back(value());
    } else if (arg == "--config") {
      parsed.config_path = value();
    } else if (is_option(arg)) {
      parsed.values[arg] = value();
    } else if (arg.size() > 1 && arg[0] == '-') {
      throw InvalidInputError(prefix + "unknown option '" + arg + "' (see coverage_tool " +
                              command + " --help)");
    } else if (parsed.mission_path.empty()) {
      parsed.mission_path = arg;
    } else {
      throw InvalidInputError(prefix + "one mission file expected, got '" + parsed.mission_path +
                              "' and '" + arg + "'");
    }
  }
  if (parsed.help) return parsed;
  if (parsed.mission_path.empty()) {
    throw InvalidInputError(prefix + "no mission file given (see coverage_tool " + command +
                            " --help)");
  }
  for (const CommandOption& option : options) {
    const auto it = parsed.values.find(option.name);
    if (!option.required && it == parsed.values.end()) continue;
    if (it == parsed.values.end() || it->second.empty()) {
      throw InvalidInputError(prefix + option.name + " " + option.value + " is required");
    }
  }
  return parsed;
}

Mission loadMission(const CommandArguments& arguments, std::ostream& out) {
  const auto start = std::chrono::steady_clock::now();
  const PlannerParameters base = arguments.config_path.empty()
                                     ? PlannerParameters{}
                                     : MissionFileReader().readParameters(arguments.config_path);
  Mission mission = readMission(arguments.mission_path, arguments.overrides, base);
  out << "load: " << arguments.mission_path << ": hull of " << mission.polygon.hull.size()
      << " vertices, " << mission.polygon.holes.size() << " holes, frame " << mission.frame_id;
  if (mission.datum) {
    out << " at datum (" << formatRoundTrip(mission.datum->latitude) << ", "
        << formatRoundTrip(mission.datum->longitude) << ")";
  }
  out << " (" << formatSeconds(secondsSince(start)) << ")" << std::endl;
  return mission;
}

std::optional<MissionCommandInput> startMissionCommand(const std::string& command,
                                                       const std::vector<std::string>& args,
                                                       const std::vector<CommandOption>& options,
                                                       const std::string& usage,
                                                       std::ostream& out) {
  CommandArguments arguments = parseCommandArguments(command, args, options);
  if (arguments.help) {
    out << usage;
    return std::nullopt;
  }
  Mission mission = loadMission(arguments, out);
  return MissionCommandInput{std::move(arguments), std::move(mission)};
}

GeoPoint parseDatum(const std::string& text) {
  const std::size_t comma = text.find(',');
  GeoPoint datum;
  const auto number = [&](std::size_t begin, std::size_t end, double& value) {
    const auto [stop, error] = std::from_chars(text.data() + begin, text.data() + end, value);
    return error == std::errc() && stop == text.data() + end && begin < end;
  };
  if (comma == std::string::npos || !number(0, comma, datum.latitude) ||
      !number(comma + 1, text.size(), datum.longitude)) {
    throw InvalidInputError("--datum " + text + ": expected LAT,LON in degrees, e.g. 47.37,8.54");
  }
  if (!(std::abs(datum.latitude) <= 90.0) || !(std::abs(datum.longitude) <= 180.0)) {
    throw InvalidInputError("--datum " + text +
                            ": the latitude must lie in [-90, 90] and the longitude in "
                            "[-180, 180] degrees (LAT,LON)");
  }
  return datum;
}

void createOutputDirectory(const std::string& dir) {
  std::error_code code;
  std::filesystem::create_directories(dir, code);
  if (code || !std::filesystem::is_directory(dir)) {
    throw InvalidInputError("cannot create the output directory " + dir +
                            (code ? ": " + code.message() : ""));
  }
}

}  // namespace kinematic_coverage::core
