// Planner reference: the figures a planner change must keep on the maps that plan today.
// Plans (as `coverage_tool plan` does: validate, clean, plan) every map of the reference
// set: the hard-map shoreline family (seeds 0 to 59, 150 to 600 vertices), the seeded lake
// maps (LakeMapGenerator, seeds 0 to 9), the shipped missions (config/missions) and the
// peer's polygons (bench/data/pcp_polygons). Prints one CSV row per map: its name, its
// vertices and holes, the plan's time_cost_s (the waypoint path's cost, which smoothing
// does not touch) and the median planning time of --runs runs.
//
// With --compare FILE (a CSV this program printed, e.g. bench/data/planner_reference.csv,
// recorded at the commit before the shoreline-scaling work), prints per map the ratios of
// time_cost_s and of the planning time to the recorded ones, the largest time-cost ratio,
// and the median time ratio over the shorelines of 500 to 600 vertices; exit status 1 when
// a map fails to plan or its time-cost ratio exceeds --max-cost-ratio (default 1.005).
// Maps not recorded are left out, so a run over fewer shorelines checks those it has.
//
// --maps NAME[,NAME...] plans only the maps named; --write-maps DIR writes each map planned
// as a mission file DIR/NAME.yaml (missionYaml: polygon, start, goal and the parameters the
// generators vary), to look at one with `coverage_tool plan`. --set NAME=VALUE (repeatable)
// plans every map with that parameter changed, to measure a planner option against the record.
//
// Usage: planner_reference [--runs R] [--shorelines N] [--compare FILE]
//                          [--max-cost-ratio X] [--maps NAME[,NAME...]] [--write-maps DIR]
//                          [--set NAME=VALUE]...
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "coverage_system/mission/mission_file_reader.h"
#include "coverage_system/mission/mission_planner.h"
#include "test/support/hard_map_generator.h"
#include "test/support/hard_map_yaml.h"
#include "test/support/lake_map_generator.h"

namespace {

using kinematic_coverage::core::Mission;

struct ReferenceMap {
  std::string name;
  Mission mission;
};

struct ReferenceRow {
  std::string name;
  std::size_t vertices = 0;
  std::size_t holes = 0;
  double time_cost_s = 0.0;
  double planning_time_s = 0.0;
};

std::vector<ReferenceMap> referenceMaps(int shorelines) {
  using kinematic_coverage::core::testing::HardMapGenerator;
  using kinematic_coverage::core::testing::LakeMapGenerator;
  using kinematic_coverage::core::testing::MapFamily;
  std::vector<ReferenceMap> maps;
  const HardMapGenerator shoreline(MapFamily::kShoreline);
  for (int seed = 0; seed < shorelines; ++seed) {
    maps.push_back({"shoreline_" + std::to_string(seed), shoreline.generate(seed).mission});
  }
  for (int seed = 0; seed < 10; ++seed) {
    maps.push_back({"lake_" + std::to_string(seed), LakeMapGenerator().generate(seed)});
  }
  for (const std::string directory : {std::string(KC_SOURCE_DIR) + "/config/missions",
                                      std::string(KC_SOURCE_DIR) + "/bench/data/pcp_polygons"}) {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(directory)) {
      if (entry.path().extension() == ".yaml") files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    for (const auto& file : files) {
      maps.push_back({file.stem().string(),
                      kinematic_coverage::core::MissionFileReader().read(file.string())});
    }
  }
  return maps;
}

std::size_t vertexCount(const Mission& mission) {
  std::size_t count = mission.polygon.hull.size();
  for (const auto& hole : mission.polygon.holes) count += hole.size();
  return count;
}

ReferenceRow measure(const ReferenceMap& map, int runs) {
  ReferenceRow row{map.name, vertexCount(map.mission), map.mission.polygon.holes.size()};
  std::vector<double> times;
  for (int run = 0; run < runs; ++run) {
    const auto planned = kinematic_coverage::core::planMission(map.mission);
    row.time_cost_s = planned.plan.time_cost_s;
    times.push_back(planned.planning_time_s);
  }
  std::sort(times.begin(), times.end());
  row.planning_time_s = times[times.size() / 2];
  return row;
}

std::map<std::string, ReferenceRow> readReference(const std::string& path) {
  std::ifstream stream(path);
  if (!stream) {
    std::fprintf(stderr, "planner_reference: cannot read %s\n", path.c_str());
    std::exit(2);
  }
  std::map<std::string, ReferenceRow> rows;
  std::string line;
  while (std::getline(stream, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("map,", 0) == 0) continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    ReferenceRow row;
    fields >> row.name >> row.vertices >> row.holes >> row.time_cost_s >> row.planning_time_s;
    if (fields) rows[row.name] = row;
  }
  return rows;
}

/// The names of a comma-separated list.
std::set<std::string> namesOf(const std::string& list) {
  std::set<std::string> names;
  std::istringstream stream(list);
  for (std::string name; std::getline(stream, name, ',');) {
    if (!name.empty()) names.insert(name);
  }
  return names;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 3;
  int shorelines = 60;
  std::string compare;
  double max_cost_ratio = 1.005;
  std::set<std::string> only;
  std::string write_maps;
  std::vector<std::string> overrides;
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument == "--runs" && i + 1 < argc) {
      runs = std::max(1, std::atoi(argv[++i]));
    } else if (argument == "--shorelines" && i + 1 < argc) {
      shorelines = std::max(0, std::atoi(argv[++i]));
    } else if (argument == "--compare" && i + 1 < argc) {
      compare = argv[++i];
    } else if (argument == "--max-cost-ratio" && i + 1 < argc) {
      max_cost_ratio = std::atof(argv[++i]);
    } else if (argument == "--set" && i + 1 < argc) {
      overrides.push_back(argv[++i]);
    } else if (argument == "--maps" && i + 1 < argc) {
      only = namesOf(argv[++i]);
    } else if (argument == "--write-maps" && i + 1 < argc) {
      write_maps = argv[++i];
    } else {
      std::fprintf(stderr,
                   "usage: planner_reference [--runs R] [--shorelines N] [--compare FILE] "
                   "[--max-cost-ratio X] [--maps NAME[,NAME...]] [--write-maps DIR] [--set "
                   "NAME=VALUE]...\n");
      return 2;
    }
  }
  const std::map<std::string, ReferenceRow> reference =
      compare.empty() ? std::map<std::string, ReferenceRow>() : readReference(compare);
  if (compare.empty()) {
    std::printf("map,vertices,holes,time_cost_s,planning_time_s\n");
  } else {
    std::printf("map,vertices,time_cost_ratio,planning_time_ratio\n");
  }
  bool failed = false;
  double worst_cost_ratio = 0.0;
  std::vector<double> large_shoreline_time_ratios;
  std::size_t compared = 0;
  for (ReferenceMap& map : referenceMaps(shorelines)) {
    if (!only.empty() && only.count(map.name) == 0) continue;
    map.mission.parameters = kinematic_coverage::core::MissionFileReader().withOverrides(
        map.mission.parameters, overrides);
    if (!write_maps.empty()) {
      std::ofstream(write_maps + "/" + map.name + ".yaml")
          << kinematic_coverage::core::testing::missionYaml(map.mission,
                                                            "planner_reference map " + map.name);
    }
    ReferenceRow row;
    try {
      row = measure(map, runs);
    } catch (const std::exception& error) {
      std::printf("%s,failed: %s\n", map.name.c_str(), error.what());
      failed = true;
      continue;
    }
    if (compare.empty()) {
      std::printf("%s,%zu,%zu,%.6f,%.4f\n", row.name.c_str(), row.vertices, row.holes,
                  row.time_cost_s, row.planning_time_s);
    } else {
      const auto it = reference.find(row.name);
      if (it == reference.end()) continue;
      ++compared;
      const double cost_ratio = row.time_cost_s / it->second.time_cost_s;
      const double time_ratio = row.planning_time_s / it->second.planning_time_s;
      worst_cost_ratio = std::max(worst_cost_ratio, cost_ratio);
      if (!(cost_ratio <= max_cost_ratio)) failed = true;
      if (row.name.rfind("shoreline_", 0) == 0 && row.vertices >= 500 && row.vertices <= 600) {
        large_shoreline_time_ratios.push_back(time_ratio);
      }
      std::printf("%s,%zu,%.5f,%.3f\n", row.name.c_str(), row.vertices, cost_ratio, time_ratio);
    }
    std::fflush(stdout);
  }
  if (!compare.empty()) {
    std::printf(
        "# %zu of %zu recorded maps; largest time-cost ratio %.5f (bar %.3f); median planning-time "
        "ratio on the %zu shorelines of 500 to 600 vertices %.3f\n",
        compared, reference.size(), worst_cost_ratio, max_cost_ratio,
        large_shoreline_time_ratios.size(), median(large_shoreline_time_ratios));
  }
  return failed ? 1 : 0;
}
