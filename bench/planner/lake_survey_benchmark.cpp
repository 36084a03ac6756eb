// Lake survey benchmark: whole lakes of 20, 100 and 500 km^2 planned as an operator plans
// them. For each area it draws a lake (test/support/survey_lake_generator.h: a noisy shore
// with islands and a survey vehicle's side-scan-like line sensor), writes it as a GeoJSON
// mission in WGS84 near --datum without a datum property (so that coverage_tool anchors
// its frame at its default datum, the centre of the lake's extent), and runs
// `coverage_tool plan` on it in a child process. Prints one table row per lake: its area,
// vertices, islands and cells, the outcome, the waypoints, the trajectory's length (also
// times the swath over the lake's area: how many times over it could sweep the lake) and
// time, the reachable area seen, the vehicle's mission items, the poses the trajectory
// files hold, and the planning time, the whole run's time and the peak resident memory.
//
// Usage: lake_survey_benchmark [--areas KM2[,KM2...]] [--seed S] [--datum LAT,LON]
//                              [--tool PATH] [--out DIR] [--plots DIR] [--timeout SECONDS]
// Defaults: --areas 20,100,500, seed 0, a datum at 47.6 N 9.4 E, coverage_tool beside this
// program, a temporary folder (removed after), 900 s per run. --plots DIR copies each
// lake's plot.png there as lake_<area>km2.png.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "bench/support/coverage_tool_run.h"
#include "coverage_system/mission/mission_frame.h"
#include "coverage_system/tool/geojson_writer.h"
#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/geometry/boundary_simplification.h"
#include "test/support/survey_lake_generator.h"

namespace {

using kinematic_coverage::core::formatDuration;
using kinematic_coverage::core::GeoPoint;
using kinematic_coverage::core::MapProjection;
using kinematic_coverage::core::Mission;
using kinematic_coverage::core::MissionFrame;

/// The number after `"key": ` in a metrics.json text; NaN when absent.
double metric(const std::string& json, const std::string& key) {
  std::smatch match;
  const std::regex number("\"" + key + "\": (-?[0-9.eE+-]+)");
  return std::regex_search(json, match, number) ? std::stod(match[1]) : std::nan("");
}

/// The first number of the first line of `output` that matches `pattern`'s group 1; "-"
/// when none.
std::string firstMatch(const std::string& output, const std::string& pattern) {
  std::smatch match;
  return std::regex_search(output, match, std::regex(pattern)) ? std::string(match[1]) : "-";
}

std::vector<double> parseAreas(const std::string& text) {
  std::vector<double> areas;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    const double area = std::atof(item.c_str());
    if (!(area > 0.0)) return {};
    areas.push_back(area);
  }
  return areas;
}

std::string readFile(const std::string& path) {
  std::ifstream stream(path);
  std::stringstream text;
  text << stream.rdbuf();
  return text.str();
}

/// Plans the lake of `area_km2` and prints its row.
void planLake(double area_km2, std::uint64_t seed, const GeoPoint& datum, const std::string& tool,
              const std::string& out, const std::string& plots, double timeout_s) {
  const Mission mission =
      kinematic_coverage::core::testing::SurveyLakeGenerator().generate(seed, area_km2);
  const std::size_t vertices =
      kinematic_coverage::core::BoundarySimplification::vertexCount(mission.polygon);
  const std::string name = "lake_" + kinematic_coverage::core::formatNumber(area_km2) + "km2";
  const std::string path = out + "/" + name + ".geojson";
  std::ofstream(path) << kinematic_coverage::core::GeoJsonWriter(
                             MissionFrame(datum, MapProjection::kLocal))
                             .mission(mission, false);
  const std::string dir = out + "/" + name;
  const kinematic_coverage::bench::CoverageToolRun run =
      kinematic_coverage::bench::runPlan(tool, path, dir, {}, timeout_s);
  const bool planned = run.finished && run.exit_status == 0;
  const std::string outcome = !run.finished ? "timed out"
                              : planned     ? "planned"
                                            : kinematic_coverage::bench::firstWords(run.output);
  const std::string json = planned ? readFile(dir + "/metrics.json") : "";
  const std::string items = firstMatch(run.output, R"(mission: \d+ waypoints[^,]*, (\d+) items)");
  const std::string poses = firstMatch(run.output, R"(thin: the trajectory files hold (\d+) of)");
  // How many times over the lanes and transits could sweep the lake: 1 for lanes that
  // neither overlap nor leave the lake.
  const double sweeps = metric(json, "trajectory_length_m") *
                        kinematic_coverage::core::testing::SurveyLakeGenerator::kSwath /
                        (area_km2 * 1e6);
  std::printf(
      "| %s | %zu | %zu | %.0f | %s | %.0f | %.1f | %.2f | %s | %.3f | %s | %s | %.2f | %.2f | "
      "%.0f |\n",
      kinematic_coverage::core::formatNumber(area_km2).c_str(), vertices,
      mission.polygon.holes.size(), metric(json, "cells"), outcome.c_str(),
      metric(json, "waypoint_count"), metric(json, "trajectory_length_m") / 1000.0, sweeps,
      planned ? formatDuration(metric(json, "traversal_time_s")).c_str() : "-",
      metric(json, "reachable_coverage_percent"), items.c_str(), poses.c_str(),
      kinematic_coverage::bench::planningSeconds(run.output), run.wall_s, run.peak_mb);
  std::fflush(stdout);
  if (planned && !plots.empty()) {
    std::filesystem::create_directories(plots);
    std::filesystem::copy_file(dir + "/plot.png", plots + "/" + name + ".png",
                               std::filesystem::copy_options::overwrite_existing);
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<double> areas = parseAreas("20,100,500");
  std::uint64_t seed = 0;
  GeoPoint datum{47.6, 9.4};
  std::string tool = (std::filesystem::path(argv[0]).parent_path() / "coverage_tool").string();
  std::string out;
  std::string plots;
  double timeout_s = 900.0;
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument == "--areas" && i + 1 < argc) {
      areas = parseAreas(argv[++i]);
    } else if (argument == "--seed" && i + 1 < argc) {
      seed = std::strtoull(argv[++i], nullptr, 10);
    } else if (argument == "--datum" && i + 1 < argc &&
               std::sscanf(argv[++i], "%lf,%lf", &datum.latitude, &datum.longitude) == 2) {
    } else if (argument == "--tool" && i + 1 < argc) {
      tool = argv[++i];
    } else if (argument == "--out" && i + 1 < argc) {
      out = argv[++i];
    } else if (argument == "--plots" && i + 1 < argc) {
      plots = argv[++i];
    } else if (argument == "--timeout" && i + 1 < argc) {
      timeout_s = std::atof(argv[++i]);
    } else {
      areas.clear();
      break;
    }
  }
  if (areas.empty()) {
    std::fprintf(stderr,
                 "usage: lake_survey_benchmark [--areas KM2[,KM2...]] [--seed S] "
                 "[--datum LAT,LON] [--tool PATH] [--out DIR] [--plots DIR] "
                 "[--timeout SECONDS]\n");
    return 2;
  }
  const bool temporary = out.empty();
  if (temporary) {
    out = (std::filesystem::temp_directory_path() /
           ("lake_survey_benchmark_" + std::to_string(getpid())))
              .string();
  }
  std::filesystem::create_directories(out);
  std::printf(
      "| lake km^2 | vertices | islands | cells | outcome | waypoints | trajectory km | "
      "trajectory x swath / area | traversal time | reachable seen %% | mission items | "
      "trajectory file poses | planning s (timing) | run s (timing) | peak MB (at most 2048) |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const double area : areas) planLake(area, seed, datum, tool, out, plots, timeout_s);
  if (temporary) std::filesystem::remove_all(out);
  return 0;
}
