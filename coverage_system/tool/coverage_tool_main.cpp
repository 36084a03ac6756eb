// coverage_tool: the ROS-free command line of the package (docs/REFERENCE.md, coverage_tool).
// Exit status: 0 success; 2 invalid input or an impossible request, with one line on
// stderr naming it; 1 an internal error (a bug on valid input), with one line naming the
// stage. Every exception is caught here.

#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "coverage_system/tool/evaluate_command.h"
#include "coverage_system/tool/export_command.h"
#include "coverage_system/tool/parameters_command.h"
#include "coverage_system/tool/plan_command.h"
#include "coverage_system/tool/replan_command.h"
#include "coverage_system/tool/simulate_command.h"
#include "polygon_coverage_ros_bridge/base/huge_page_heap.h"
#include "polygon_coverage_ros_bridge/geometry/internal_error.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/gtsp/gtsp_command.h"

namespace kinematic_coverage::core {
namespace {

constexpr int kExitSuccess = 0;
constexpr int kExitInternalError = 1;
constexpr int kExitInvalidInput = 2;

const char* const kUsage =
    "usage: coverage_tool COMMAND [ARGS...]\n"
    "commands:\n"
    "  plan MISSION.yaml --out DIR [--config FILE] [--set name=value ...]\n"
    "      plan a coverage path: DIR/waypoints.csv, trajectory.csv, metrics.json, plot.png;\n"
    "      MISSION.geojson (WGS84) also gives DIR/waypoints.geojson, trajectory.geojson\n"
    "  evaluate MISSION.yaml --trajectory FILE.csv --out DIR [--set name=value ...]\n"
    "      coverage of a trajectory (x,y,yaw[,t,kind] CSV): DIR/metrics.json, DIR/plot.png\n"
    "  replan MISSION.yaml --updated UPDATED.yaml --visited FILE.csv --out DIR [--set ...]\n"
    "      replan the remaining area after obstacles moved: the files of plan and\n"
    "      DIR/remaining.yaml\n"
    "  simulate MISSION.yaml --trajectory FILE.csv --out DIR [--set name=value ...]\n"
    "      a robot model follows a trajectory: DIR/actual.csv, metrics.json, plot.png\n"
    "  export MISSION.yaml --datum LAT,LON --out FILE.geojson\n"
    "      the mission as a geo-referenced GeoJSON (WGS84), which plan reads back\n"
    "  parameters [--markdown]\n"
    "      every parameter with its default, unit, valid values and description\n"
    "  gtsp INSTANCE.gtsp [--seed N] [--time-limit S]\n"
    "      solve a GTSPLIB instance; prints one JSON line\n"
    "--config FILE: parameters from FILE (e.g. config/thesis.yaml, the thesis's settings)\n"
    "before the mission file's; --set: one parameter, after it.\n"
    "Run coverage_tool COMMAND --help for a command's options.\n"
    "Exit status: 0 success, 2 invalid input (one line on stderr), 1 internal error.\n";

/// The message on one line: a line break inside would split the one-line report.
std::string oneLine(std::string message) {
  for (char& c : message) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return message;
}

int runCommand(const std::vector<std::string>& args) {
  if (args.empty()) {
    throw InvalidInputError("no command given (see coverage_tool --help)");
  }
  const std::string& command = args.front();
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (command == "--help" || command == "-h" || command == "help") {
    std::cout << kUsage;
    return kExitSuccess;
  }
  if (command == "plan") {
    PlanCommand().run(rest, std::cout, std::cerr);
    return kExitSuccess;
  }
  if (command == "gtsp") return runGtspCommand(rest, std::cout, std::cerr);
  if (command == "evaluate") {
    EvaluateCommand().run(rest, std::cout, std::cerr);
    return kExitSuccess;
  }
  if (command == "replan") {
    ReplanCommand().run(rest, std::cout, std::cerr);
    return kExitSuccess;
  }
  if (command == "simulate") {
    SimulateCommand().run(rest, std::cout, std::cerr);
    return kExitSuccess;
  }
  if (command == "parameters") {
    ParametersCommand().run(rest, std::cout);
    return kExitSuccess;
  }
  if (command == "export") {
    ExportCommand().run(rest, std::cout, std::cerr);
    return kExitSuccess;
  }
  throw InvalidInputError("unknown command '" + command + "' (see coverage_tool --help)");
}

}  // namespace
}  // namespace kinematic_coverage::core

int main(int argc, char** argv) {
  using namespace kinematic_coverage::core;
  restartWithHugePageHeap(argv);
  try {
    return runCommand(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const InvalidInputError& error) {
    std::cerr << "error: " << oneLine(error.what()) << std::endl;
    return kExitInvalidInput;
  } catch (const InternalError& error) {
    std::cerr << "internal error: " << oneLine(error.what())
              << " (a bug of the package, not of the input: please report it with the mission "
                 "file)"
              << std::endl;
    return kExitInternalError;
  } catch (const std::exception& error) {
    std::cerr << "internal error: " << oneLine(error.what()) << std::endl;
    return kExitInternalError;
  } catch (...) {
    std::cerr << "internal error: unknown exception" << std::endl;
    return kExitInternalError;
  }
}
