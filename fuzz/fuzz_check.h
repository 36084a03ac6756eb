#pragma once

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::fuzz {

/// Aborts with `message` when a property that must hold for every input is violated, so
/// that libFuzzer reports the input as a crash.
inline void fuzzCheck(bool holds, const std::string& message) {
  if (holds) return;
  std::fprintf(stderr, "fuzz property violated: %s\n", message.c_str());
  std::abort();
}

/// Runs `body`; InvalidInputError, the expected outcome for invalid input (docs/REFERENCE.md,
/// Geometry and input rules), is swallowed; any other exception aborts with its message.
template <typename Body>
void runExpectingOnlyInvalidInput(Body body) {
  try {
    body();
  } catch (const core::InvalidInputError&) {
    return;
  } catch (const std::exception& error) {
    fuzzCheck(false, std::string("unexpected exception: ") + error.what());
  } catch (...) {
    fuzzCheck(false, "unexpected non-standard exception");
  }
}

}  // namespace kinematic_coverage::fuzz
