// Scaling benchmark: planning time and peak memory against the size of a chart.
// For each chart (test/support/hard_map_generator.h: HardMapGenerator::lakeChart by shore
// vertices and islands, roughShore likewise, archipelago by islands; default parameters) it
// writes the chart as a mission file and runs `coverage_tool plan` on it in a child process,
// as a user would: planning, smoothing, sampling and coverage evaluation included. Prints one
// table row per map: its kind, shore vertices and islands, all vertices, the cells, the
// outcome (planned, or the error's first words), the planning time and the whole run's time,
// the peak resident memory (the child's ru_maxrss) and the slowest stage with its time; then
// each map's stage lines.
//
// Usage: scaling_benchmark [--sizes CHART[,CHART...]] [--seeds S] [--tool PATH] [--out DIR]
//                          [--timeout SECONDS] [--plot FILE.png] [--set NAME=VALUE]...
// CHART is V:I (a lake chart of V shore vertices and I islands), rough:V:I (a rough shore)
// or archipelago:I. Defaults: --sizes
// 500:10,1000:20,2000:40,5000:100,10000:200,rough:2000:40,rough:10000:200,archipelago:2000,
// one seed, coverage_tool beside this program, a temporary folder (removed after), 900 s per
// run (a run past it counts as timed out). Then the growth exponents of the lake charts'
// planning time, run time and peak memory against vertices, whether each goal is met, and
// with --plot a log-log PNG of the lake charts' times. --set NAME=VALUE (repeatable) is handed
// to `coverage_tool plan`, to measure a parameter (boundary_simplification=0.05). Every rough
// shore and archipelago is planned once more with ten times the generalized TSP's effort
// (gtsp_effort=10), and its tour's cost (the solve stage's) compared: a line per chart and
// the goal that none is more than kEffortGoalRatio times dearer.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
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

/// One chart to plan: its kind ("lake", "rough shore", "archipelago"), shore vertices (0 for
/// an archipelago's square) and islands.
struct Chart {
  std::string kind;
  int vertices = 0;
  int islands = 0;

  HardMap generate(int seed) const {
    if (kind == "rough shore") return HardMapGenerator::roughShore(seed, vertices, islands);
    if (kind == "archipelago") return HardMapGenerator::archipelago(seed, islands);
    return HardMapGenerator::lakeChart(seed, vertices, islands);
  }
  /// The mission file's name for `seed`.
  std::string name(int seed) const {
    const std::string prefix = kind == "rough shore"   ? "rough_"
                               : kind == "archipelago" ? "archipelago_"
                                                       : "chart_";
    return prefix + (kind == "archipelago" ? "" : std::to_string(vertices) + "_") +
           std::to_string(islands) + "_" + std::to_string(seed);
  }
};

/// The charts of a --sizes list; none when an item is malformed.
std::vector<Chart> parseCharts(const std::string& text) {
  std::vector<Chart> charts;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    std::vector<std::string> fields;
    std::stringstream item_stream(item);
    std::string field;
    while (std::getline(item_stream, field, ':')) fields.push_back(field);
    if (fields.size() == 2 && fields[0] == "archipelago") {
      charts.push_back({"archipelago", 0, std::atoi(fields[1].c_str())});
    } else if (fields.size() == 3 && fields[0] == "rough") {
      charts.push_back({"rough shore", std::atoi(fields[1].c_str()), std::atoi(fields[2].c_str())});
    } else if (fields.size() == 2) {
      charts.push_back({"lake", std::atoi(fields[0].c_str()), std::atoi(fields[1].c_str())});
    } else {
      return {};
    }
  }
  return charts;
}

/// What one chart's run measured, or the most a goal allows (0: no goal).
struct Measured {
  double planning_s = 0.0;
  double run_s = 0.0;
  double peak_mb = 0.0;
};

/// A chart and the most its run may take.
struct Goal {
  Chart chart;
  Measured most;
};

}  // namespace

/// The goals: the project's lake charts of 2 000 and 10 000 vertices plan within 2 and 30 s;
/// the rough shores of 2 000 vertices and 40 islands plan within 2 s and run within 4 s, of
/// 10 000 and 200 within 60 s and 2 GB; the archipelago of 2 000 islands within 120 s and 4 GB.
constexpr double kChart2000GoalSeconds = 2.0;
constexpr double kChart10000GoalSeconds = 30.0;
const Goal kGoals[] = {{{"lake", 2000, 40}, {kChart2000GoalSeconds, 0.0, 0.0}},
                       {{"lake", 10000, 200}, {kChart10000GoalSeconds, 0.0, 0.0}},
                       {{"rough shore", 2000, 40}, {2.0, 4.0, 0.0}},
                       {{"rough shore", 10000, 200}, {60.0, 0.0, 2048.0}},
                       {{"archipelago", 0, 2000}, {120.0, 0.0, 4096.0}}};

/// A tour may cost at most this many times the tour found with ten times the effort.
constexpr double kEffortGoalRatio = 1.01;
/// The generalized TSP's effort of the comparison runs (gtsp_effort).
constexpr double kComparisonEffort = 10.0;

/// The tour cost of the solve stage's line (0 when there is none).
double tourCost(const std::string& output) {
  std::smatch cost;
  const std::regex solve_line(R"(solve: visiting order of \d+ cells, cost ([0-9.eE+-]+))");
  return std::regex_search(output, cost, solve_line) ? std::atof(std::string(cost[1]).c_str())
                                                     : 0.0;
}

/// Plans the chart's mission again with kComparisonEffort times the generalized TSP's effort;
/// returns the ratio of the two tours' costs (0 when either run failed), and in `line` both
/// costs.
double effortRatio(const std::string& tool, const std::string& mission, const std::string& dir,
                   std::vector<std::string> settings, double timeout_s, const std::string& name,
                   double tour_cost, std::string* line) {
  settings.push_back("gtsp_effort=" + std::to_string(kComparisonEffort));
  const kinematic_coverage::bench::CoverageToolRun run =
      kinematic_coverage::bench::runPlan(tool, mission, dir, settings, timeout_s);
  const double longer = run.finished && run.exit_status == 0 ? tourCost(run.output) : 0.0;
  const double ratio = longer > 0.0 && tour_cost > 0.0 ? tour_cost / longer : 0.0;
  double solve_s = 0.0;
  for (const auto& [stage, seconds] : kinematic_coverage::bench::stageTimes(run.output)) {
    if (stage == "solve") solve_s = seconds;
  }
  char text[256];
  std::snprintf(text, sizeof(text),
                "effort: %s: tour cost %.1f, %.1f with %.0f times the effort (solve %.1f s): "
                "ratio %.4f",
                name.c_str(), tour_cost, longer, kComparisonEffort, solve_s, ratio);
  *line = text;
  return ratio;
}

/// One line per goal whose chart was planned (its slowest seed): what it measured and
/// whether that met the goal; a chart that was run but not planned misses it.
void printGoals(const std::map<std::string, Measured>& planned, const std::set<std::string>& run) {
  for (const Goal& goal : kGoals) {
    const std::string key = goal.chart.name(0);
    if (run.count(key) == 0) continue;
    const auto found = planned.find(key);
    std::printf("goal: the %s of %d vertices and %d islands", goal.chart.kind.c_str(),
                goal.chart.vertices, goal.chart.islands);
    if (found == planned.end()) {
      std::printf(" was not planned: MISSED\n");
      continue;
    }
    const Measured& m = found->second;
    const Measured& most = goal.most;
    bool met = m.planning_s <= most.planning_s;
    std::printf(" planned within %.0f s: %.2f s", most.planning_s, m.planning_s);
    if (most.run_s > 0.0) {
      std::printf(", run within %.0f s: %.2f s", most.run_s, m.run_s);
      met = met && m.run_s <= most.run_s;
    }
    if (most.peak_mb > 0.0) {
      std::printf(", within %.0f MB: %.0f MB", most.peak_mb, m.peak_mb);
      met = met && m.peak_mb <= most.peak_mb;
    }
    std::printf(": %s\n", met ? "met" : "MISSED");
  }
}

int main(int argc, char** argv) {
  std::vector<Chart> sizes = parseCharts(
      "500:10,1000:20,2000:40,5000:100,10000:200,rough:2000:40,rough:10000:200,archipelago:2000");
  int seeds = 1;
  std::string tool = (std::filesystem::path(argv[0]).parent_path() / "coverage_tool").string();
  std::string out;
  double timeout_s = 900.0;
  std::string plot;
  std::vector<std::string> settings;
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument == "--sizes" && i + 1 < argc) {
      sizes = parseCharts(argv[++i]);
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
    std::fprintf(
        stderr,
        "usage: scaling_benchmark [--sizes V:I|rough:V:I|archipelago:I[,...]] [--seeds S] "
        "[--tool PATH] [--out DIR] [--timeout SECONDS] [--plot FILE.png] [--set NAME=VALUE]...\n");
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
      "| chart | shore vertices | islands | vertices | cells | outcome | planning s (timing) "
      "| run s (timing) | peak MB (at most 4096) | estimate MB | estimate / peak (varies) | "
      "slowest stage (timing) "
      "|\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<std::string> details;
  std::vector<std::pair<double, double>> planning_times;  // (vertices, s) of planned charts
  std::vector<std::pair<double, double>> run_times;
  std::vector<std::pair<double, double>> peaks;  // (vertices, MB)
  std::map<std::string, Measured>
      worst_by_chart;  // chart name (seed 0) -> its slowest seed's figures
  std::set<std::string> run_charts;
  std::vector<double> estimate_ratios;  // estimate / peak of the planned charts
  std::vector<double> effort_ratios;    // tour cost over the one at ten times the effort
  std::vector<std::string> effort_lines;
  for (const Chart& size : sizes) {
    for (int seed = 0; seed < seeds; ++seed) {
      const HardMap map = size.generate(seed);
      std::size_t vertices = map.mission.polygon.hull.size();
      for (const auto& hole : map.mission.polygon.holes) vertices += hole.size();
      const std::string name = size.name(seed);
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
      // The planner's memory estimate (the decompose stage's line, or a refusal's message).
      std::smatch estimate;
      const std::regex estimate_line(R"((?:memory estimate|would need about) (\d+) MB)");
      const double estimate_mb = std::regex_search(run.output, estimate, estimate_line)
                                     ? std::atof(std::string(estimate[1]).c_str())
                                     : 0.0;
      const double estimate_ratio = run.peak_mb > 0.0 ? estimate_mb / run.peak_mb : 0.0;
      const std::string outcome = !run.finished ? "timed out"
                                  : run.exit_status == 0
                                      ? "planned"
                                      : kinematic_coverage::bench::firstWords(run.output);
      std::printf(
          "| %s | %d | %zu | %zu | %s | %s | %.2f | %.2f | %.0f | %.0f | %.2f | %s %.2f s |\n",
          size.kind.c_str(), size.vertices, map.mission.polygon.holes.size(), vertices,
          cell_count.c_str(), outcome.c_str(), planning_s, run.wall_s, run.peak_mb, estimate_mb,
          estimate_ratio, slowest.first.c_str(), slowest.second);
      if (run.finished && run.exit_status == 0) {
        estimate_ratios.push_back(estimate_ratio);
      }
      std::fflush(stdout);
      run_charts.insert(size.name(0));
      if (run.finished && run.exit_status == 0) {
        if (size.kind == "lake") {
          planning_times.emplace_back(static_cast<double>(vertices), planning_s);
          run_times.emplace_back(static_cast<double>(vertices), run.wall_s);
          peaks.emplace_back(static_cast<double>(vertices), run.peak_mb);
        }
        Measured& worst = worst_by_chart[size.name(0)];
        worst = {std::max(worst.planning_s, planning_s), std::max(worst.run_s, run.wall_s),
                 std::max(worst.peak_mb, run.peak_mb)};
      }
      if (run.finished && run.exit_status == 0 && size.kind != "lake") {
        effort_lines.emplace_back();
        effort_ratios.push_back(effortRatio(tool, mission, out + "/" + name + "_effort", settings,
                                            timeout_s, name, tourCost(run.output),
                                            &effort_lines.back()));
      }
      std::ostringstream detail;
      detail << name << ":";
      for (const auto& [stage, seconds] : stages) detail << " " << stage << " " << seconds;
      details.push_back(detail.str());
    }
  }
  std::printf("\n");
  for (const std::string& detail : details) std::printf("    %s\n", detail.c_str());
  if (!effort_lines.empty()) std::printf("\n");
  for (const std::string& line : effort_lines) std::printf("%s\n", line.c_str());
  std::printf(
      "\nGrowth exponents over the planned lake charts (least-squares slope of log value against "
      "log "
      "vertices; nan with fewer than two sizes): planning time %.2f, whole run %.2f, peak "
      "memory %.2f\n",
      kinematic_coverage::bench::growthExponent(planning_times),
      kinematic_coverage::bench::growthExponent(run_times),
      kinematic_coverage::bench::growthExponent(peaks));
  printGoals(worst_by_chart, run_charts);
  if (!estimate_ratios.empty()) {
    const auto [low, high] = std::minmax_element(estimate_ratios.begin(), estimate_ratios.end());
    std::printf(
        "goal: the memory estimate within 0.5 to 2 times the peak of every planned chart: "
        "%.2f to %.2f: %s\n",
        *low, *high, *low >= 0.5 && *high <= 2.0 ? "met" : "MISSED");
  }
  if (!effort_ratios.empty()) {
    const double worst = *std::max_element(effort_ratios.begin(), effort_ratios.end());
    const bool failed = *std::min_element(effort_ratios.begin(), effort_ratios.end()) <= 0.0;
    std::printf(
        "goal: every tour of a rough shore or archipelago at most %.2f times the one with %.0f "
        "times the effort: %.4f: %s\n",
        kEffortGoalRatio, kComparisonEffort, worst,
        !failed && worst <= kEffortGoalRatio ? "met" : "MISSED");
  }
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
