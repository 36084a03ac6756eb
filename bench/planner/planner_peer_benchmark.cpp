// Side by side with the peer planner (ethz-asl/polygon_coverage_planning) on its example
// polygons: plans each mission of bench/data/pcp_polygons with the same settings and
// prints our figures next to the peer's published figures from that folder's README.
//
//   planner_peer_benchmark [POLYGONS_DIR] [--runs N]
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "coverage_system/mission/mission_file_reader.h"
#include "coverage_system/mission/mission_planner.h"
#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/geometry/wall_offset.h"
#include "trajectory_generation_tools/coverage/coverage_evaluator.h"

namespace {

using kinematic_coverage::core::CoveragePlan;

/// One row of the peer's table in the README.
struct PeerFigures {
  int cells = 0;
  int waypoints = 0;
  double path_length_m = 0.0;
  double time_cost_s = 0.0;
  double planning_time_s = 0.0;
};

/// Reads the rows "| name [(...)] | cells | waypoints | length | time cost | time |".
std::map<std::string, PeerFigures> readPeerTable(const std::string& readme) {
  std::map<std::string, PeerFigures> table;
  std::ifstream in(readme);
  std::string line;
  while (std::getline(in, line)) {
    if (line.size() < 2 || line[0] != '|') continue;
    std::vector<std::string> fields;
    std::stringstream stream(line.substr(1));
    std::string field;
    while (std::getline(stream, field, '|')) fields.push_back(field);
    if (fields.size() < 6) continue;
    std::stringstream name_stream(fields[0]);
    std::string name;
    name_stream >> name;
    PeerFigures figures;
    try {
      figures.cells = std::stoi(fields[1]);
      figures.waypoints = std::stoi(fields[2]);
      figures.path_length_m = std::stod(fields[3]);
      figures.time_cost_s = std::stod(fields[4]);
      figures.planning_time_s = std::stod(fields[5]);
    } catch (const std::exception&) {
      continue;  // the header and separator rows
    }
    table[name] = figures;
  }
  return table;
}

}  // namespace

int main(int argc, char** argv) {
  std::string directory = KC_PEER_POLYGONS_DIR;
  int runs = 3;
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument == "--runs" && i + 1 < argc) {
      runs = std::max(1, std::atoi(argv[++i]));
    } else {
      directory = argument;
    }
  }
  const auto peer = readPeerTable(directory + "/README.md");
  std::vector<std::string> missions;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    if (entry.path().extension() == ".yaml") missions.push_back(entry.path().string());
  }
  std::sort(missions.begin(), missions.end());

  std::printf(
      "| polygon | cells (peer) | waypoints (peer) | path length m (peer) | time cost s (peer) "
      "| time cost ratio | planning time s, median (timing) (peer) | reachable area seen %% |\n"
      "|---|---|---|---|---|---|---|---|\n");
  for (const std::string& path : missions) {
    const std::string name = std::filesystem::path(path).stem().string();
    try {
      const auto mission = kinematic_coverage::core::MissionFileReader().read(path);
      kinematic_coverage::core::PlannedMission planned;
      std::vector<double> times;
      for (int run = 0; run < runs; ++run) {
        planned = kinematic_coverage::core::planMission(mission);
        times.push_back(planned.planning_time_s);
      }
      const CoveragePlan& plan = planned.plan;
      std::sort(times.begin(), times.end());
      const double median_time = times[times.size() / 2];
      const double seen = kinematic_coverage::core::waypointPathReachableCoveragePercent(
          planned.free_area,
          kinematic_coverage::core::exactOffsetParts(
              planned.free_area, mission.parameters.wall_distance, plan.offset_parts),
          kinematic_coverage::core::sensorOf(mission.parameters), plan.waypoints);
      const auto it = peer.find(name);
      if (it == peer.end()) {
        std::printf("| %s | %zu | %zu | %.2f | %.2f | - | %.4f | %.2f |\n", name.c_str(),
                    plan.cells.size(), plan.waypoints.size(), plan.path_length_m, plan.time_cost_s,
                    median_time, seen);
      } else {
        const PeerFigures& reference = it->second;
        std::printf(
            "| %s | %zu (%d) | %zu (%d) | %.2f (%.2f) | %.2f (%.2f) | %.3f | %.4f (%.2f) | %.2f "
            "|\n",
            name.c_str(), plan.cells.size(), reference.cells, plan.waypoints.size(),
            reference.waypoints, plan.path_length_m, reference.path_length_m, plan.time_cost_s,
            reference.time_cost_s, plan.time_cost_s / reference.time_cost_s, median_time,
            reference.planning_time_s, seen);
      }
      std::fflush(stdout);
    } catch (const std::exception& error) {
      std::printf("| %s | failed: %s |\n", name.c_str(), error.what());
    }
  }
  return 0;
}
