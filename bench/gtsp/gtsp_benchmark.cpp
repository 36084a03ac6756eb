// GTSPLIB benchmark of the GTSP solver: every instance of the benchmark set in bench/data
// (or a selection) with several seeds; prints a markdown table of instance, nodes, clusters,
// optimum, mean gap %, best gap %, the runs that came near the time limit (their gap is not
// seed-determined) and mean time s (solver time, parsing excluded).
//
//   gtsp_benchmark [--dir GTSPLIB_DIR] [--instances name,name,...] [--seeds N]
//                  [--time-limit S] [--population N] [--stall N] [--neighbours N]

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "polygon_coverage_ros_bridge/gtsp/gtsp_instance.h"
#include "polygon_coverage_ros_bridge/gtsp/gtsplib_reader.h"

namespace {

using kinematic_coverage::core::GtsplibProblem;
using kinematic_coverage::core::GtsplibReader;
using kinematic_coverage::core::GtspOptions;
using kinematic_coverage::core::GtspSolution;

/// One line of optima.tsv.
struct Reference {
  std::string name;
  double optimum = 0.0;
};

std::vector<Reference> readOptima(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::vector<Reference> references;
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    Reference reference;
    std::string nodes;
    std::string clusters;
    std::getline(fields, reference.name, '\t');
    std::getline(fields, nodes, '\t');
    std::getline(fields, clusters, '\t');
    fields >> reference.optimum;
    if (!reference.name.empty()) references.push_back(reference);
  }
  return references;
}

std::string findInstance(const std::string& dir, const std::string& name) {
  for (const char* kind : {"symmetric", "asymmetric"}) {
    const std::string path = dir + "/instances/" + kind + "/" + name + ".gtsp";
    if (std::ifstream(path)) return path;
  }
  return "";
}

std::vector<std::string> splitComma(const std::string& text) {
  std::vector<std::string> words;
  std::istringstream in(text);
  std::string word;
  while (std::getline(in, word, ',')) {
    if (!word.empty()) words.push_back(word);
  }
  return words;
}

}  // namespace

int main(int argc, char** argv) {
  std::string dir = KC_GTSPLIB_DIR;
  std::vector<std::string> selection;
  int seeds = 5;
  GtspOptions options;
  options.time_limit_s = 120.0;
  options.threads = 1;  // one thread, as the published solvers' times it is read against
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (i + 1 >= argc) {
      std::cerr << "gtsp_benchmark: " << word << " needs a value\n";
      return 2;
    }
    const std::string value = argv[++i];
    if (word == "--dir") {
      dir = value;
    } else if (word == "--instances") {
      selection = splitComma(value);
    } else if (word == "--seeds") {
      seeds = std::max(1, std::atoi(value.c_str()));
    } else if (word == "--time-limit") {
      options.time_limit_s = std::atof(value.c_str());
    } else if (word == "--population") {
      options.population_size = std::atoi(value.c_str());
    } else if (word == "--neighbours") {
      options.neighbour_count = std::atoi(value.c_str());
    } else if (word == "--stall") {
      options.stall_generations = std::atoi(value.c_str());
    } else {
      std::cerr << "gtsp_benchmark: unknown option " << word << "\n";
      return 2;
    }
  }
  try {
    const std::vector<Reference> references = readOptima(dir + "/optima.tsv");
    std::cout
        << "| instance | nodes | clusters | optimum | mean gap % | best gap % | runs at the time "
           "limit | mean time s (timing) |\n"
        << "|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const Reference& reference : references) {
      if (!selection.empty() &&
          std::find(selection.begin(), selection.end(), reference.name) == selection.end()) {
        continue;
      }
      const std::string path = findInstance(dir, reference.name);
      if (path.empty()) {
        std::cerr << "gtsp_benchmark: no file for " << reference.name << "\n";
        continue;
      }
      const GtsplibProblem problem = GtsplibReader::readFile(path);
      double gap_sum = 0.0;
      double best_gap = 1e300;
      double time_sum = 0.0;
      int limited_runs = 0;
      for (int seed = 1; seed <= seeds; ++seed) {
        GtspOptions run = options;
        run.seed = static_cast<unsigned>(seed);
        const auto start = std::chrono::steady_clock::now();
        const GtspSolution solution = kinematic_coverage::core::solveGtsp(problem.instance, run);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        time_sum += seconds;
        // A run this close to the cap may have been cut by it: its gap is not seed-determined.
        if (seconds >= 0.9 * run.time_limit_s) ++limited_runs;
        const double gap = 100.0 * (solution.cost - reference.optimum) / reference.optimum;
        gap_sum += gap;
        best_gap = std::min(best_gap, gap);
      }
      std::cout << std::fixed << "| " << reference.name << " | " << problem.instance.node_count
                << " | " << problem.instance.clusters.size() << " | " << std::setprecision(0)
                << reference.optimum << " | " << std::setprecision(3) << gap_sum / seeds << " | "
                << best_gap << " | " << limited_runs << " | " << std::setprecision(2)
                << time_sum / seeds << " |" << std::endl;
    }
  } catch (const std::exception& error) {
    std::cerr << "gtsp_benchmark: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
