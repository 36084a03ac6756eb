#pragma once

#include <sstream>
#include <string>

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

}  // namespace kinematic_coverage::core
