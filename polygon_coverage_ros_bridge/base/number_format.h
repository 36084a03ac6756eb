#pragma once

#include <charconv>
#include <cmath>
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

/// `value` rounded to `decimals` decimal places; formatRoundTrip then writes at most that
/// many, since the double nearest a short decimal reads back as it.
inline double roundToDecimals(double value, int decimals) {
  const double scale = std::pow(10.0, decimals);
  return std::round(value * scale) / scale;
}

/// A duration for progress lines, to the millisecond: "0.016 s".
inline std::string formatSeconds(double seconds) {
  std::ostringstream out;
  out.precision(3);
  out << std::fixed << seconds << " s";
  return out.str();
}

/// A length for people: "190.8 m" under a kilometre, "11.74 km" beyond.
inline std::string formatLength(double metres) {
  std::ostringstream out;
  out << std::fixed;
  if (std::abs(metres) < 999.95) {
    out.precision(1);
    out << metres << " m";
  } else {
    out.precision(2);
    out << metres / 1000.0 << " km";
  }
  return out.str();
}

/// A duration for people, in the units that read at its size: "42.5 s" under a minute,
/// "6 min 05 s" under an hour, "3 h 07 min" under a day, "2 d 14 h 05 min" beyond, each
/// rounded to its last unit; a negative or non-finite duration as formatNumber writes it.
inline std::string formatDuration(double seconds) {
  if (!(seconds >= 0.0) || !std::isfinite(seconds)) return formatNumber(seconds) + " s";
  std::ostringstream out;
  if (seconds < 59.95) {
    out.precision(1);
    out << std::fixed << seconds << " s";
    return out.str();
  }
  const auto two = [](long long value) { return (value < 10 ? "0" : "") + std::to_string(value); };
  const long long whole_seconds = std::llround(seconds);
  if (whole_seconds < 3600) {
    out << whole_seconds / 60 << " min " << two(whole_seconds % 60) << " s";
    return out.str();
  }
  const long long minutes = std::llround(seconds / 60.0);
  if (minutes < 24 * 60) {
    out << minutes / 60 << " h " << two(minutes % 60) << " min";
    return out.str();
  }
  out << minutes / (24 * 60) << " d " << two(minutes / 60 % 24) << " h " << two(minutes % 60)
      << " min";
  return out.str();
}

}  // namespace kinematic_coverage::core
