// The thesis's two experiments (Chapter 4, Tables 4.1 and 4.3) as a sensitivity study of
// the simulated robot's controllers: the same smoothed and unsmoothed trajectories driven
// by each controller (setpoint, timed, pose_stream, los), varying one of its own parameters
// at a time around the experiment's robot (yaw_gain 1, 2, 5, 10; tracking_natural_frequency
// 0.5, 1, 2; pose_rate 0.5, 1, 2 Hz; los_lookahead 0.5, 1, 2 turning radii; sway actuated
// or not), in calm water and in the lake with several disturbance seeds. Prints per
// experiment a table of the ratios smoothed / unsmoothed (time; error by mean and by sum,
// the nearest-point error sampled at 2 Hz) with the lake's median and spread, and whether
// each of the thesis's trends appears; then one paragraph saying where they appear.
//
//   controller_study [--seeds 5] [--lake name=value ...] \
//       --experiment 1|2 MISSION.yaml SMOOTHED.csv UNSMOOTHED.csv [--set name=value ...] ...
//
// The trajectories are the pose files (with their t column) of `coverage_tool plan`; the
// robot is the mission's parameters with the experiment's --set, the row's and, in the
// lake, the --lake settings and disturbance_seed 1 to --seeds. scripts/run_experiments.sh
// runs it for docs/EXPERIMENTS.md.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "bench/support/median.h"
#include "coverage_system/mission/mission_file_reader.h"
#include "coverage_system/mission/pose_csv_reader.h"
#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "trajectory_generation_tools/simulation/robot_simulator.h"

namespace kinematic_coverage::core {
namespace {

/// The thesis's figures of one experiment: traversal times (s) and tracking error sums (m),
/// smoothed and unsmoothed (Tables 4.1 and 4.3), one run each in Lake Zurich.
struct ThesisExperiment {
  const char* id;
  double time_smoothed_s;
  double time_unsmoothed_s;
  double error_smoothed_m;
  double error_unsmoothed_m;
  double timeRatio() const { return time_smoothed_s / time_unsmoothed_s; }
  double errorRatio() const { return error_smoothed_m / error_unsmoothed_m; }
};
constexpr ThesisExperiment kThesis[] = {{"1", 1529.0, 1241.0, 293.44, 452.20},
                                        {"2", 531.0, 703.0, 283.98, 239.34}};

/// The levels of each controller's own parameters (los_lookahead in turning radii).
constexpr double kYawGains[] = {1.0, 2.0, 5.0, 10.0};
constexpr double kNaturalFrequencies[] = {0.5, 1.0, 2.0};
constexpr double kPoseRates[] = {0.5, 1.0, 2.0};
constexpr double kLookaheadShares[] = {0.5, 1.0, 2.0};

/// One experiment of the command line.
struct Experiment {
  const ThesisExperiment* thesis = nullptr;
  std::string mission;
  std::vector<Pose2> poses[2];  ///< smoothed, unsmoothed
  std::vector<double> times[2];
  std::vector<std::string> robot;  ///< its --set
};

struct StudyOptions {
  int seeds = 5;
  std::vector<std::string> lake;
  std::vector<Experiment> experiments;
};

/// A row of the study: a controller with one of its parameters changed (or none).
struct StudySetting {
  std::string controller;
  std::string label;
  std::vector<std::string> overrides;
};

/// A trajectory's figures under one setting and condition; arrived false when the robot
/// did not reach the last pose within sim_time_limit.
struct RunFigures {
  bool arrived = false;
  double time_s = 0.0;
  double error_mean_m = 0.0;
  double error_sum_m = 0.0;
};

/// Smoothed over unsmoothed: time, error by mean, error by sum (NaN where a run failed or
/// the unsmoothed figure is 0).
struct Ratios {
  double time = NAN;
  double error_mean = NAN;
  double error_sum = NAN;
};

[[noreturn]] void usage(const std::string& problem) {
  std::fprintf(stderr,
               "controller_study: %s\nusage: controller_study [--seeds N] [--lake name=value ...] "
               "--experiment 1|2 MISSION.yaml SMOOTHED.csv UNSMOOTHED.csv [--set name=value ...] "
               "...\n",
               problem.c_str());
  std::exit(2);
}

void readTrajectory(const std::string& path, std::vector<Pose2>& poses,
                    std::vector<double>& times) {
  const PoseTable table = PoseCsvReader().read(path);
  if (!table.has_time) usage(path + " has no t column");
  for (const PoseRecord& row : table.rows) {
    poses.push_back(row.pose);
    times.push_back(row.t);
  }
}

StudyOptions parseOptions(int argc, char** argv) {
  StudyOptions options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--seeds" && has_value) {
      options.seeds = std::atoi(argv[++i]);
      if (options.seeds < 1) usage("--seeds must be at least 1");
    } else if (arg == "--lake" && has_value) {
      options.lake.push_back(argv[++i]);
    } else if (arg == "--set" && has_value && !options.experiments.empty()) {
      options.experiments.back().robot.push_back(argv[++i]);
    } else if (arg == "--experiment" && i + 4 < argc) {
      Experiment experiment;
      const std::string id = argv[++i];
      for (const ThesisExperiment& thesis : kThesis) {
        if (id == thesis.id) experiment.thesis = &thesis;
      }
      if (!experiment.thesis) usage("no thesis experiment '" + id + "' (1 or 2)");
      experiment.mission = argv[++i];
      for (int k = 0; k < 2; ++k)
        readTrajectory(argv[++i], experiment.poses[k], experiment.times[k]);
      options.experiments.push_back(std::move(experiment));
    } else {
      usage("unexpected argument '" + arg + "'");
    }
  }
  if (options.experiments.empty()) usage("no --experiment");
  return options;
}

/// Each controller's rows: its baseline (the experiment's robot), then each level of its
/// own parameters that differs from the baseline, then its vehicle without sway actuation.
std::vector<StudySetting> settingsOf(const PlannerParameters& base) {
  std::vector<StudySetting> settings;
  auto add = [&](const std::string& controller, const std::string& name, double level,
                 double baseline, double scale = 1.0, const std::string& unit = "") {
    if (level == baseline) return;
    settings.push_back({controller,
                        controller + ": " + name + " " + formatNumber(level) + unit,
                        {"controller=" + controller, name + "=" + formatNumber(level * scale)}});
  };
  for (const std::string controller : {"setpoint", "timed", "pose_stream", "los"}) {
    settings.push_back({controller, controller + ": baseline", {"controller=" + controller}});
    if (controller == "setpoint" || controller == "los") {
      for (const double gain : {1.0, 2.0, 5.0, 10.0})
        add(controller, "yaw_gain", gain, base.yaw_gain);
    }
    if (controller == "timed" || controller == "pose_stream") {
      for (const double wn : kNaturalFrequencies) {
        add(controller, "tracking_natural_frequency", wn, base.tracking_natural_frequency);
      }
    }
    if (controller == "pose_stream") {
      for (const double rate : kPoseRates) add(controller, "pose_rate", rate, base.pose_rate);
    }
    if (controller == "los") {
      const double baseline =
          base.los_lookahead > 0.0 ? base.los_lookahead / base.turning_radius : 1.0;
      for (const double share : kLookaheadShares) {
        add(controller, "los_lookahead", share, baseline, base.turning_radius, " x turning_radius");
      }
    }
    settings.push_back({controller,
                        controller + ": sway_actuated false",
                        {"controller=" + controller, "sway_actuated=false"}});
  }
  return settings;
}

RunFigures simulateRun(const Experiment& experiment, int trajectory,
                       const std::vector<std::string>& overrides) {
  const Mission mission = MissionFileReader().read(experiment.mission, overrides);
  RunFigures figures;
  try {
    const SimulationResult result =
        RobotSimulator(robotModelOf(mission.parameters))
            .simulate(experiment.poses[trajectory], experiment.times[trajectory]);
    figures.arrived = true;
    figures.time_s = result.traversal_time_s;
    figures.error_mean_m = result.sampled_tracking.mean_m;
    figures.error_sum_m = result.sampled_tracking.sum_m;
  } catch (const InvalidInputError& error) {
    std::fprintf(stderr, "controller_study: %s\n", error.what());
  }
  return figures;
}

double ratio(double smoothed, double unsmoothed) {
  return unsmoothed > 0.0 ? smoothed / unsmoothed : NAN;
}

/// The ratios of one setting under one condition (`condition`: extra overrides).
Ratios ratiosOf(const Experiment& experiment, const StudySetting& setting,
                const std::vector<std::string>& condition) {
  std::vector<std::string> overrides = experiment.robot;
  overrides.insert(overrides.end(), setting.overrides.begin(), setting.overrides.end());
  overrides.insert(overrides.end(), condition.begin(), condition.end());
  const RunFigures smoothed = simulateRun(experiment, 0, overrides);
  const RunFigures unsmoothed = simulateRun(experiment, 1, overrides);
  Ratios ratios;
  if (!smoothed.arrived || !unsmoothed.arrived) return ratios;
  ratios.time = ratio(smoothed.time_s, unsmoothed.time_s);
  ratios.error_mean = ratio(smoothed.error_mean_m, unsmoothed.error_mean_m);
  ratios.error_sum = ratio(smoothed.error_sum_m, unsmoothed.error_sum_m);
  return ratios;
}

std::string ratioText(double value) {
  if (!std::isfinite(value)) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", value);
  return text;
}

/// Median and spread over the seeds: "1.23 (1.20 to 1.25)".
std::string spreadText(const std::vector<double>& values) {
  std::vector<double> finite;
  for (const double value : values) {
    if (std::isfinite(value)) finite.push_back(value);
  }
  if (finite.empty()) return "-";
  const auto [low, high] = std::minmax_element(finite.begin(), finite.end());
  std::string text =
      ratioText(bench::median(finite)) + " (" + ratioText(*low) + " to " + ratioText(*high) + ")";
  if (finite.size() < values.size())
    text += ", " + std::to_string(values.size() - finite.size()) + " failed";
  return text;
}

/// Whether `value` lies on the thesis's side of 1.
bool sameSide(double value, double thesis) {
  return std::isfinite(value) && (value > 1.0) == (thesis > 1.0) && value != 1.0;
}

/// How often one trend appeared, per controller: in calm water (settings) and in the lake
/// (settings x seeds).
struct TrendCount {
  int calm = 0;
  int calm_of = 0;
  int lake = 0;
  int lake_of = 0;
};

/// Per controller (in settings order), the time and error trends' counts.
struct ExperimentTrends {
  std::vector<std::string> controllers;
  std::vector<TrendCount> time;
  std::vector<TrendCount> error;
};

TrendCount& countFor(ExperimentTrends& trends, std::vector<TrendCount>& counts,
                     const std::string& controller) {
  const auto found = std::find(trends.controllers.begin(), trends.controllers.end(), controller);
  return counts[static_cast<std::size_t>(found - trends.controllers.begin())];
}

/// One row of an experiment's table, counting its trends into `trends`.
std::string studyRow(const Experiment& experiment, const StudySetting& setting,
                     const StudyOptions& options, ExperimentTrends& trends) {
  const ThesisExperiment& thesis = *experiment.thesis;
  const Ratios calm = ratiosOf(experiment, setting, {});
  std::vector<double> time, mean, sum;
  int time_trend = 0;
  int error_trend = 0;
  for (int seed = 1; seed <= options.seeds; ++seed) {
    std::vector<std::string> condition = options.lake;
    condition.push_back("disturbance_seed=" + std::to_string(seed));
    const Ratios lake = ratiosOf(experiment, setting, condition);
    time.push_back(lake.time);
    mean.push_back(lake.error_mean);
    sum.push_back(lake.error_sum);
    time_trend += sameSide(lake.time, thesis.timeRatio());
    error_trend += sameSide(lake.error_sum, thesis.errorRatio());
  }
  const bool calm_time = sameSide(calm.time, thesis.timeRatio());
  const bool calm_error = sameSide(calm.error_sum, thesis.errorRatio());
  for (auto [counts, calm_hit, lake_hits] : {std::tuple{&trends.time, calm_time, time_trend},
                                             std::tuple{&trends.error, calm_error, error_trend}}) {
    TrendCount& count = countFor(trends, *counts, setting.controller);
    count.calm += calm_hit;
    ++count.calm_of;
    count.lake += lake_hits;
    count.lake_of += options.seeds;
  }
  const std::string seeds = " of " + std::to_string(options.seeds);
  std::ostringstream row;
  row << "| " << setting.label << " | " << ratioText(calm.time) << " | "
      << ratioText(calm.error_mean) << " | " << ratioText(calm.error_sum) << " | "
      << spreadText(time) << " | " << spreadText(mean) << " | " << spreadText(sum) << " | "
      << (calm_time ? "yes" : "no") << "; " << time_trend << seeds << " | "
      << (calm_error ? "yes" : "no") << "; " << error_trend << seeds << " |";
  return row.str();
}

/// "1, 2, 5 and 10".
template <std::size_t n>
std::string levelsText(const double (&levels)[n]) {
  std::string text;
  for (std::size_t i = 0; i < n; ++i) {
    text += (i == 0 ? "" : i + 1 == n ? " and " : ", ") + formatNumber(levels[i]);
  }
  return text;
}

/// "`a=1`, `b=2`".
std::string settingsText(const std::vector<std::string>& settings) {
  std::string text;
  for (std::size_t i = 0; i < settings.size(); ++i) {
    text += (i == 0 ? "`" : ", `") + settings[i] + "`";
  }
  return text;
}

/// The paragraph that says what the tables hold.
void printIntroduction(const StudyOptions& options) {
  std::printf(
      "Each controller drives the same two trajectories of each experiment, varying one of its "
      "own parameters at a time around the experiment's robot: `yaw_gain` %s (setpoint, los), "
      "`tracking_natural_frequency` %s rad/s (timed, pose_stream), `pose_rate` %s Hz "
      "(pose_stream), `los_lookahead` %s times the turning radius (los), and each with the "
      "torpedo-like vehicle (`sway_actuated: false`); each in calm water with exact navigation "
      "and in the lake (%s) with `disturbance_seed` 1 to %d. A ratio is the smoothed run's figure "
      "over the unsmoothed run's; the error is the distance to the nearest point of the desired "
      "path sampled at %s Hz (`tracking_error_2hz_mean_m` and `tracking_error_2hz_sum_m`, "
      "docs/REFERENCE.md, Metrics); a lake cell gives the median over the seeds and their range; "
      "a thesis's trend appears where the ratio lies on the thesis's side of 1 (its ratios in "
      "the first row; the error trend by the sum, the thesis's metric).\n\n",
      levelsText(kYawGains).c_str(), levelsText(kNaturalFrequencies).c_str(),
      levelsText(kPoseRates).c_str(), levelsText(kLookaheadShares).c_str(),
      settingsText(options.lake).c_str(), options.seeds, formatNumber(kErrorSampleRate).c_str());
}

/// The table of one experiment; its trend counts into `trends`.
void printExperiment(const Experiment& experiment, const StudyOptions& options,
                     ExperimentTrends& trends) {
  const ThesisExperiment& thesis = *experiment.thesis;
  const PlannerParameters base =
      MissionFileReader().read(experiment.mission, experiment.robot).parameters;
  const std::vector<StudySetting> settings = settingsOf(base);
  std::printf("Experiment %s (`%s`%s%s):\n\n", thesis.id,
              std::filesystem::path(experiment.mission).filename().string().c_str(),
              experiment.robot.empty() ? "" : ", robot ", settingsText(experiment.robot).c_str());
  for (const StudySetting& setting : settings) {
    if (std::find(trends.controllers.begin(), trends.controllers.end(), setting.controller) ==
        trends.controllers.end()) {
      trends.controllers.push_back(setting.controller);
      trends.time.emplace_back();
      trends.error.emplace_back();
    }
  }
  std::printf(
      "| setting | time ratio, calm | error ratio by mean, calm | error ratio by sum, calm | "
      "time ratio, lake | error ratio by mean, lake | error ratio by sum, lake | thesis's time "
      "trend: calm; lake | thesis's error trend: calm; lake |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  std::printf("| thesis (Proteus, one run in Lake Zurich) | - | - | - | %s | - | %s | - | - |\n",
              ratioText(thesis.timeRatio()).c_str(), ratioText(thesis.errorRatio()).c_str());
  for (const StudySetting& setting : settings) {
    std::fprintf(stderr, "controller_study: experiment %s, %s\n", thesis.id, setting.label.c_str());
    std::printf("%s\n", studyRow(experiment, setting, options, trends).c_str());
  }
  std::printf("\n");
}

/// "setpoint in 5 of 5 calm and 25 of 25 lake runs, timed in 0 of 4 and 0 of 20" for one
/// trend of one experiment.
std::string trendSentence(const ExperimentTrends& trends, const std::vector<TrendCount>& counts) {
  std::string text;
  for (std::size_t i = 0; i < trends.controllers.size(); ++i) {
    const TrendCount& count = counts[i];
    text += (i == 0                               ? ""
             : i + 1 == trends.controllers.size() ? " and "
                                                  : ", ") +
            trends.controllers[i] + " in " + std::to_string(count.calm) + " of " +
            std::to_string(count.calm_of) + (i == 0 ? " calm" : "") + " and " +
            std::to_string(count.lake) + " of " + std::to_string(count.lake_of) +
            (i == 0 ? " lake runs" : "");
  }
  return text;
}

void printSummary(const StudyOptions& options, const std::vector<ExperimentTrends>& all) {
  std::string text =
      "Where the thesis's trends appear and where they do not (per controller, the calm and "
      "the lake runs of its rows whose ratio lies on the thesis's side of 1):";
  for (std::size_t e = 0; e < all.size(); ++e) {
    const ThesisExperiment& thesis = *options.experiments[e].thesis;
    const bool smoothed_slower = thesis.timeRatio() > 1.0;
    const bool smoothed_worse = thesis.errorRatio() > 1.0;
    text += std::string(" in experiment ") + thesis.id + ", the " +
            (smoothed_slower ? "unsmoothed" : "smoothed") +
            " run faster: " + trendSentence(all[e], all[e].time) + "; the smoothed run tracked " +
            (smoothed_worse ? "worse" : "better") + ": " + trendSentence(all[e], all[e].error) +
            (e + 1 == all.size() ? "." : ";");
  }
  std::printf("%s\n", text.c_str());
}

int run(int argc, char** argv) {
  const StudyOptions options = parseOptions(argc, argv);
  printIntroduction(options);
  std::vector<ExperimentTrends> trends(options.experiments.size());
  for (std::size_t e = 0; e < options.experiments.size(); ++e) {
    printExperiment(options.experiments[e], options, trends[e]);
  }
  printSummary(options, trends);
  return 0;
}

}  // namespace
}  // namespace kinematic_coverage::core

int main(int argc, char** argv) {
  try {
    return kinematic_coverage::core::run(argc, argv);
  } catch (const kinematic_coverage::core::InvalidInputError& error) {
    std::fprintf(stderr, "controller_study: %s\n", error.what());
    return 2;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "controller_study: internal error: %s\n", error.what());
    return 1;
  }
}
