#include "polygon_coverage_ros_bridge/base/huge_page_heap.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace kinematic_coverage::core {
namespace {

/// What the probe prints when run by the shell with `environment` before it.
std::string probeOutput(const std::string& environment) {
  const std::string command =
      environment + " '" + std::string(KC_HUGE_PAGE_PROBE_PATH) + "' first 'second word'";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return "popen failed";
  std::string output;
  char buffer[256];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  pclose(pipe);
  return output;
}

TEST(HugePageHeap, RestartsOnceWithTheTunableAndTheSameArguments) {
  EXPECT_EQ(probeOutput("env -u GLIBC_TUNABLES"),
            std::string(kHugePageHeapTunable) + "\nfirst\nsecond word\n");
}

TEST(HugePageHeap, KeepsTheCallersTunables) {
  EXPECT_EQ(probeOutput("GLIBC_TUNABLES=glibc.malloc.perturb=0"),
            "glibc.malloc.perturb=0\nfirst\nsecond word\n");
  // Set and empty: the way to opt out.
  EXPECT_EQ(probeOutput("GLIBC_TUNABLES="), "\nfirst\nsecond word\n");
}

}  // namespace
}  // namespace kinematic_coverage::core
