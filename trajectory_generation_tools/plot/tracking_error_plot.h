#pragma once

#include <string>
#include <vector>

namespace kinematic_coverage::core {

/// What a tracking-error plot shows: a simulated run's errors, one per simulation step
/// (`actual.csv` of coverage_tool simulate), as in the thesis's Fig. 4.5.
struct TrackingErrorPlotData {
  std::vector<double> t;        ///< s from the start
  std::vector<double> error;    ///< m, the distance to the nearest point of the path, >= 0
  std::vector<double> error_x;  ///< m, the robot's x less the nearest point's (signed)
  std::vector<double> error_y;  ///< m, the same along y
  /// Lines above the plot: the first is the title (bold), the others key figures.
  std::vector<std::string> title_lines;
};

/// The mean and standard deviation of values: the normal distribution fitted to them by
/// maximum likelihood (Fig. 4.5b's Gaussian fits).
struct NormalFit {
  double mean = 0.0;
  double standard_deviation = 0.0;
};

/// Renders `errors.png` of coverage_tool simulate with cairo: the histogram of the
/// error with its normal fit (Fig. 4.5a and b), the histograms of its x and y parts with
/// theirs, and the x, y and Euclidean errors over time (Fig. 4.5c).
class TrackingErrorPlot {
 public:
  /// Bars of each histogram.
  static constexpr int kBins = 40;

  /// An image `width` pixels wide (and 0.8 times as high). Throws InvalidInputError for a
  /// width outside [CoveragePlotOptions::kMinSide, 4096].
  explicit TrackingErrorPlot(int width = 1200);

  /// Renders `data` and writes it to `path` as PNG. Throws InvalidInputError for no
  /// steps, series of different lengths, a non-finite value, a negative error or times
  /// that decrease, and naming `path` when the file cannot be written.
  void writePng(const TrackingErrorPlotData& data, const std::string& path) const;

  /// The normal distribution fitted to `values` (all zeros for none).
  static NormalFit fit(const std::vector<double>& values);

  /// Counts of `values` in kBins equal bins over [low, high] (a value at `high` in the
  /// last bin; values outside left out).
  static std::vector<int> histogram(const std::vector<double>& values, double low, double high);

 private:
  int width_;
};

}  // namespace kinematic_coverage::core
