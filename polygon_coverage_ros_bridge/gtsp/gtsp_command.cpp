#include "polygon_coverage_ros_bridge/gtsp/gtsp_command.h"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <limits>
#include <sstream>

#include "polygon_coverage_ros_bridge/base/elapsed_seconds.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/gtsp/gtsp_instance.h"
#include "polygon_coverage_ros_bridge/gtsp/gtsplib_reader.h"

namespace kinematic_coverage::core {
namespace {

constexpr char kUsage[] = "usage: coverage_tool gtsp INSTANCE.gtsp [--seed N] [--time-limit S]";

struct GtspCommandArguments {
  std::string path;
  GtspOptions options;
};

GtspCommandArguments parseArguments(const std::vector<std::string>& args) {
  GtspCommandArguments parsed;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& word = args[i];
    if (word == "--seed" || word == "--time-limit") {
      if (i + 1 >= args.size()) throw InvalidInputError(word + " needs a value; " + kUsage);
      const std::string& value = args[++i];
      char* end = nullptr;
      if (word == "--seed") {
        const unsigned long long seed = std::strtoull(value.c_str(), &end, 10);
        if (value.empty() || *end != '\0' || value[0] == '-' ||
            seed > std::numeric_limits<unsigned>::max()) {
          throw InvalidInputError("--seed '" + value + "' is not a non-negative integer");
        }
        parsed.options.seed = static_cast<unsigned>(seed);
      } else {
        const double limit = std::strtod(value.c_str(), &end);
        if (value.empty() || *end != '\0' || !std::isfinite(limit) || limit <= 0.0) {
          throw InvalidInputError("--time-limit '" + value + "' is not a positive number");
        }
        parsed.options.time_limit_s = limit;
      }
    } else if (!word.empty() && word[0] == '-') {
      throw InvalidInputError("unknown option '" + word + "'; " + kUsage);
    } else if (parsed.path.empty()) {
      parsed.path = word;
    } else {
      throw InvalidInputError("more than one instance file given; " + std::string(kUsage));
    }
  }
  if (parsed.path.empty()) throw InvalidInputError(std::string("no instance file; ") + kUsage);
  return parsed;
}

}  // namespace

int runGtspCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  try {
    const GtspCommandArguments parsed = parseArguments(args);
    const GtsplibProblem problem = GtsplibReader::readFile(parsed.path);
    const auto start = std::chrono::steady_clock::now();
    const GtspSolution solution = solveGtsp(problem.instance, parsed.options);
    const double seconds = secondsSince(start);
    std::ostringstream line;
    line << "{\"cost\": " << std::llround(solution.cost) << ", \"time_s\": " << seconds
         << ", \"time_capped\": " << (solution.time_capped ? "true" : "false") << ", \"tour\": [";
    for (std::size_t i = 0; i < solution.nodes.size(); ++i) {
      line << (i > 0 ? ", " : "") << solution.nodes[i] + 1;
    }
    line << "]}";
    out << line.str() << "\n";
    return 0;
  } catch (const InvalidInputError& error) {
    err << "coverage_tool gtsp: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    err << "coverage_tool gtsp: internal error: " << error.what() << "\n";
    return 1;
  }
}

}  // namespace kinematic_coverage::core
