#pragma once

#include <string>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core::testing {

/// The message of the InvalidInputError that `action` throws ("" when none), for tests that
/// check what an error names.
template <typename Action>
std::string invalidInputMessage(Action action) {
  try {
    action();
  } catch (const InvalidInputError& error) {
    return error.what();
  }
  return "";
}

}  // namespace kinematic_coverage::core::testing
