// Scaling benchmark: planning time and peak memory against the size of a lake chart.
// For each size (shore vertices and islands; test/support/hard_map_generator.h,
// HardMapGenerator::lakeChart, default parameters) it writes the chart as a mission file
// and runs `coverage_tool plan` on it in a child process, as a user would: planning,
// smoothing, sampling and coverage evaluation included. Prints one table row per map:
// its vertices and islands, the cells, the outcome (planned, or the error's first words),
// the planning time and the whole run's time, the peak resident memory (the child's
// ru_maxrss) and the slowest stage with its time; then each map's stage lines.
//
// Usage: scaling_benchmark [--sizes V:I[,V:I...]] [--seeds S] [--tool PATH] [--out DIR]
//                          [--timeout SECONDS] [--plot FILE.png] [--set NAME=VALUE]...
// Defaults: --sizes 500:10,1000:20,2000:40,5000:100,10000:200, one seed, coverage_tool
// beside this program, a temporary folder (removed after), 300 s per run (a run past it
// counts as timed out). Then the growth exponents of planning time, run time and peak memory
// against vertices, and with --plot a log-log PNG of the times. --set NAME=VALUE (repeatable)
// is handed to `coverage_tool plan`, to measure a parameter (boundary_simplification=0.05).
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bench/support/coverage_tool_run.h"
#include "bench/support/log_log_plot.h"
#include "test/support/hard_map_generator.h"
#include "test/support/hard_map_yaml.h"

namespace {

using kinematic_coverage::core::testing::HardMap;
using kinematic_coverage::core::testing::HardMapGenerator;

struct Size {
  int vertices;
  int islands;
};

std::vector<Size> parseSizes(const std::string& text) {
  std::vector<Size> sizes;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    const auto colon = item.find(':');
    if (colon == std::string::npos) return {};
    sizes.push_back(
        {std::atoi(item.substr(0, colon).c_str()), std::atoi(item.substr(colon + 1).c_str())});
  }
  return sizes;
}

}  // namespace

/// The planning-time goals (s) of the 2 000- and the 10 000-vertex chart.
constexpr double kChart2000GoalSeconds = 2.0;
constexpr double kChart10000GoalSeconds = 30.0;
constexpr std::pair<int, double> kPlanningGoals[] = {{2000, kChart2000GoalSeconds},
                                                     {10000, kChart10000GoalSeconds}};

/// One line per goal whose chart was planned: its planning time and whether it met the goal.
void printGoals(const std::map<int, double>& planning_s) {
  for (const auto& [vertices, goal_s] : kPlanningGoals) {
    const auto found = planning_s.find(vertices);
    if (found == planning_s.end()) continue;
    std::printf("goal: the %d-vertex chart planned within %.0f s: %.2f s, %s\n", vertices, goal_s,
                found->second, found->second <= goal_s ? "met" : "MISSED");
  }
}

int main(int argc, char** argv) {
  std::vector<Size> sizes = parseSizes("500:10,1000:20,2000:40,5000:100,10000:200");
  int seeds = 1;
  std::string tool = (std::filesystem::path(argv[0]).parent_path() / "coverage_tool").string();
  std::string out;
  double timeout_s = 300.0;
  std::string plot;
  std::vector<std::string> settings;
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument == "--sizes" && i + 1 < argc) {
      sizes = parseSizes(argv[++i]);
    } else if (argument == "--seeds" && i + 1 < argc) {
      seeds = std::max(1, std::atoi(argv[++i]));
    } else if (argument == "--tool" && i + 1 < argc) {
      tool = argv[++i];
    } else if (argument == "--out" && i + 1 < argc) {
      out = argv[++i];
    } else if (argument == "--timeout" && i + 1 < argc) {
      timeout_s = std::atof(argv[++i]);
    } else if (argument == "--plot" && i + 1 < argc) {
      plot = argv[++i];
    } else if (argument == "--set" && i + 1 < argc) {
      settings.push_back(argv[++i]);
    } else {
      sizes.clear();
      break;
    }
  }
  if (sizes.empty()) {
    std::fprintf(stderr,
                 "usage: scaling_benchmark [--sizes V:I[,V:I...]] [--seeds S] [--tool PATH] "
                 "[--out DIR] [--timeout SECONDS] [--plot FILE.png] [--set NAME=VALUE]...\n");
    return 2;
  }
  const bool temporary = out.empty();
  if (temporary) {
    out =
        (std::filesystem::temp_directory_path() / ("scaling_benchmark_" + std::to_string(getpid())))
            .string();
  }
  std::filesystem::create_directories(out);

  std::printf(
      "| shore vertices | islands | vertices | cells | outcome | planning s (timing) | run s "
      "(timing) "
      "| peak MB (at most 2048) | slowest stage (timing) "
      "|\n|---|---|---|---|---|---|---|---|---|\n");
  std::vector<std::string> details;
  std::vector<std::pair<double, double>> planning_times;  // (vertices, s) of planned charts
  std::vector<std::pair<double, double>> run_times;
  std::vector<std::pair<double, double>> peaks;  // (vertices, MB)
  std::map<int, double> slowest_planning;        // shore vertices -> s, over the seeds
  for (const Size& size : sizes) {
    for (int seed = 0; seed < seeds; ++seed) {
      const HardMap map = HardMapGenerator::lakeChart(seed, size.vertices, size.islands);
      std::size_t vertices = map.mission.polygon.hull.size();
      for (const auto& hole : map.mission.polygon.holes) vertices += hole.size();
      const std::string name = "chart_" + std::to_string(size.vertices) + "_" +
                               std::to_string(size.islands) + "_" + std::to_string(seed);
      const std::string mission = out + "/" + name + ".yaml";
      std::ofstream(mission) << kinematic_coverage::core::testing::hardMapYaml(map);
      const kinematic_coverage::bench::CoverageToolRun run =
          kinematic_coverage::bench::runPlan(tool, mission, out + "/" + name, settings, timeout_s);
      const auto stages = kinematic_coverage::bench::stageTimes(run.output);
      // coverage_tool's own figure: validation, cleaning and planning, as metrics.json's
      // planning_time_s.
      const double planning_s = kinematic_coverage::bench::planningSeconds(run.output);
      std::pair<std::string, double> slowest{"-", 0.0};
      for (const auto& [stage, seconds] : stages) {
        if (seconds > slowest.second) slowest = {stage, seconds};
      }
      std::smatch cells;
      const std::regex cell_line(R"((\d+) [a-z]+ cells)");
      const std::string cell_count =
          std::regex_search(run.output, cells, cell_line) ? std::string(cells[1]) : "-";
      const std::string outcome = !run.finished ? "timed out"
                                  : run.exit_status == 0
                                      ? "planned"
                                      : kinematic_coverage::bench::firstWords(run.output);
      std::printf("| %d | %zu | %zu | %s | %s | %.2f | %.2f | %.0f | %s %.2f s |\n", size.vertices,
                  map.mission.polygon.holes.size(), vertices, cell_count.c_str(), outcome.c_str(),
                  planning_s, run.wall_s, run.peak_mb, slowest.first.c_str(), slowest.second);
      std::fflush(stdout);
      if (run.finished && run.exit_status == 0) {
        planning_times.emplace_back(static_cast<double>(vertices), planning_s);
        run_times.emplace_back(static_cast<double>(vertices), run.wall_s);
        peaks.emplace_back(static_cast<double>(vertices), run.peak_mb);
        slowest_planning[size.vertices] = std::max(slowest_planning[size.vertices], planning_s);
      }
      std::ostringstream detail;
      detail << name << ":";
      for (const auto& [stage, seconds] : stages) detail << " " << stage << " " << seconds;
      details.push_back(detail.str());
    }
  }
  std::printf("\n");
  for (const std::string& detail : details) std::printf("    %s\n", detail.c_str());
  std::printf(
      "\nGrowth exponents over the planned charts (least-squares slope of log value against log "
      "vertices; nan with fewer than two sizes): planning time %.2f, whole run %.2f, peak "
      "memory %.2f\n",
      kinematic_coverage::bench::growthExponent(planning_times),
      kinematic_coverage::bench::growthExponent(run_times),
      kinematic_coverage::bench::growthExponent(peaks));
  printGoals(slowest_planning);
  if (!plot.empty()) {
    kinematic_coverage::bench::writeLogLogPlot(
        plot, "Lake charts: time against size (coverage_tool plan, default parameters)",
        "vertices (shore and islands)", "seconds",
        {{"planning (metrics.json planning_time_s)", planning_times, 0.12, 0.38, 0.71},
         {"whole run (smoothing, coverage, files)", run_times, 0.85, 0.37, 0.05}});
  }
  if (temporary) std::filesystem::remove_all(out);
  return 0;
}
