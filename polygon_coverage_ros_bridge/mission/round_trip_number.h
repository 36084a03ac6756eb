#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

namespace kinematic_coverage {

/// The shortest decimal text (15 to 17 significant digits) that reads back as exactly
/// `value`, for CSV and JSON outputs: "0.1", not "0.10000000000000001". `value` must be
/// finite.
inline std::string formatRoundTrip(double value) {
  char text[40];
  for (int precision = 15; precision <= 17; ++precision) {
    std::snprintf(text, sizeof(text), "%.*g", precision, value);
    if (std::strtod(text, nullptr) == value) break;
  }
  return text;
}

}  // namespace kinematic_coverage
