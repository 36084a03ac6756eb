#include "bench/support/coverage_tool_run.h"

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>

namespace kinematic_coverage::bench {

CoverageToolRun runPlan(const std::string& tool, const std::string& mission, const std::string& dir,
                        const std::vector<std::string>& settings, double timeout_s) {
  std::vector<std::string> arguments = {tool, "plan", mission, "--out", dir};
  for (const std::string& setting : settings) {
    arguments.push_back("--set");
    arguments.push_back(setting);
  }
  std::vector<char*> argv;
  for (std::string& argument : arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);
  const std::string log = dir + ".log";
  const auto start = std::chrono::steady_clock::now();
  std::fflush(stdout);  // or the child would write what this process has buffered again
  const pid_t child = fork();
  if (child == 0) {
    std::FILE* out = std::freopen(log.c_str(), "w", stdout);
    if (out == nullptr || dup2(fileno(stdout), fileno(stderr)) < 0) _exit(127);
    execv(tool.c_str(), argv.data());
    _exit(127);
  }
  CoverageToolRun run;
  int status = 0;
  struct rusage usage {};
  while (true) {
    const pid_t done = wait4(child, &status, WNOHANG, &usage);
    run.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (done == child) {
      run.finished = true;
      run.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      break;
    }
    if (run.wall_s > timeout_s) {
      kill(child, SIGKILL);
      wait4(child, &status, 0, &usage);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  run.peak_mb = usage.ru_maxrss / 1024.0;
  std::ifstream stream(log);
  std::stringstream text;
  text << stream.rdbuf();
  run.output = text.str();
  return run;
}

std::vector<std::pair<std::string, double>> stageTimes(const std::string& output) {
  std::vector<std::pair<std::string, double>> stages;
  const std::regex line(R"(^([a-z_ ]+): .*\((\d+\.\d+) s\)$)");
  std::stringstream stream(output);
  std::string text;
  while (std::getline(stream, text)) {
    std::smatch match;
    if (std::regex_match(text, match, line)) stages.emplace_back(match[1], std::stod(match[2]));
  }
  return stages;
}

std::string firstWords(const std::string& output) {
  std::stringstream stream(output);
  std::string text;
  std::string last;
  while (std::getline(stream, text)) {
    if (text.rfind("error: ", 0) == 0) return text.substr(0, 90);
    if (!text.empty()) last = text;
  }
  return last.substr(0, 90);
}

double planningSeconds(const std::string& output) {
  std::smatch planning;
  const std::regex planning_line(R"(planning took (\d+\.\d+) s)");
  return std::regex_search(output, planning, planning_line) ? std::stod(planning[1]) : 0.0;
}

}  // namespace kinematic_coverage::bench
