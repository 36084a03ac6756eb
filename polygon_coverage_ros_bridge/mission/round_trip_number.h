#pragma once

#include <charconv>
#include <string>
#include <system_error>

namespace kinematic_coverage::core {

/// The shortest decimal text that reads back as exactly `value`, for CSV and JSON
/// outputs: "0.1", not "0.10000000000000001". `value` must be finite.
inline std::string formatRoundTrip(double value) {
  char text[40];
  const std::to_chars_result result = std::to_chars(text, text + sizeof(text), value);
  return std::string(text, result.ptr);
}

}  // namespace kinematic_coverage::core
