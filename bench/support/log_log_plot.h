#pragma once

#include <string>
#include <utility>
#include <vector>

namespace kinematic_coverage::bench {

/// One series of a log-log plot: points with x, y > 0, drawn as dots joined by a line.
struct LogLogSeries {
  std::string label;
  std::vector<std::pair<double, double>> points;
  double red = 0.0;
  double green = 0.0;
  double blue = 0.0;
};

/// The least-squares slope of log y against log x, the exponent k of y ~ x^k that a
/// scaling benchmark reports; NaN with fewer than two distinct x.
double growthExponent(const std::vector<std::pair<double, double>>& points);

/// Writes `series` as a PNG log-log plot with a grid line per decade, the axes titled and a
/// legend. Points with x or y not positive are left out. Throws std::runtime_error when
/// the file cannot be written.
void writeLogLogPlot(const std::string& path, const std::string& title, const std::string& x_title,
                     const std::string& y_title, const std::vector<LogLogSeries>& series);

}  // namespace kinematic_coverage::bench
