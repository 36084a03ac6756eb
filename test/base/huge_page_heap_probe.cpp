// A program for huge_page_heap_test: restarts as the planning programs do, then prints its
// GLIBC_TUNABLES ("(unset)" without one) and its arguments, one per line.

#include <cstdio>
#include <cstdlib>

#include "polygon_coverage_ros_bridge/base/huge_page_heap.h"

int main(int argc, char** argv) {
  kinematic_coverage::core::restartWithHugePageHeap(argv);
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  std::printf("%s\n", tunables != nullptr ? tunables : "(unset)");
  for (int i = 1; i < argc; ++i) std::printf("%s\n", argv[i]);
  return 0;
}
