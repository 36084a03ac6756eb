#pragma once

#include <charconv>
#include <sstream>
#include <string>
#include <system_error>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// A number for an error message or a log line: up to 10 significant digits, so that
/// UTM-sized coordinates stay readable ("5234567.89", not "5.23457e+06").
inline std::string formatNumber(double value) {
  std::ostringstream out;
  out.precision(10);
  out << value;
  return out.str();
}

/// A point for an error message or a log line: "(x, y)".
inline std::string formatPoint(const Point2& point) {
  return "(" + formatNumber(point.x()) + ", " + formatNumber(point.y()) + ")";
}

/// The shortest decimal text that reads back as exactly `value`, for CSV and JSON
/// outputs: "0.1", not "0.10000000000000001". `value` must be finite.
inline std::string formatRoundTrip(double value) {
  char text[40];
  const std::to_chars_result result = std::to_chars(text, text + sizeof(text), value);
  return std::string(text, result.ptr);
}

/// A duration for progress lines, to the millisecond: "0.016 s".
inline std::string formatSeconds(double seconds) {
  std::ostringstream out;
  out.precision(3);
  out << std::fixed << seconds << " s";
  return out.str();
}

}  // namespace kinematic_coverage::core
