#pragma once

#include <chrono>

namespace kinematic_coverage::core {

/// Seconds since `start` on the steady clock: the one clock of stage timings, progress
/// lines and benchmarks (immune to wall-clock jumps).
inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace kinematic_coverage::core
