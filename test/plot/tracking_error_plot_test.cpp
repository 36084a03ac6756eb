#include "trajectory_generation_tools/plot/tracking_error_plot.h"

#include <cairo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {
namespace {

/// Errors of a robot that drifts off and back every 10 s.
TrackingErrorPlotData run() {
  TrackingErrorPlotData data;
  for (int i = 1; i <= 600; ++i) {
    const double t = 0.1 * i;
    const double x = 0.2 * std::sin(2.0 * M_PI * t / 10.0);
    const double y = 0.05 * std::cos(2.0 * M_PI * t / 7.0);
    data.t.push_back(t);
    data.error_x.push_back(x);
    data.error_y.push_back(y);
    data.error.push_back(std::hypot(x, y));
  }
  data.title_lines = {"Test run", "60 s"};
  return data;
}

std::string tempPng(const std::string& name) {
  const std::string path = ::testing::TempDir() + "tracking_error_plot_" + name + ".png";
  std::remove(path.c_str());
  return path;
}

TEST(TrackingErrorPlotTest, FitsTheMeanAndDeviationByMaximumLikelihood) {
  const NormalFit fit = TrackingErrorPlot::fit({1.0, 2.0, 3.0, 4.0});
  EXPECT_DOUBLE_EQ(fit.mean, 2.5);
  EXPECT_DOUBLE_EQ(fit.standard_deviation, std::sqrt(1.25));
  const NormalFit none = TrackingErrorPlot::fit({});
  EXPECT_EQ(none.mean, 0.0);
  EXPECT_EQ(none.standard_deviation, 0.0);
}

TEST(TrackingErrorPlotTest, CountsValuesInEqualBinsWithTheTopInTheLast) {
  std::vector<double> values;
  for (int i = 0; i < TrackingErrorPlot::kBins; ++i) values.push_back(i + 0.5);
  values.push_back(TrackingErrorPlot::kBins);  // the top: in the last bin
  values.push_back(-1.0);                      // outside: left out
  const std::vector<int> counts =
      TrackingErrorPlot::histogram(values, 0.0, TrackingErrorPlot::kBins);
  ASSERT_EQ(counts.size(), static_cast<std::size_t>(TrackingErrorPlot::kBins));
  for (int i = 0; i + 1 < TrackingErrorPlot::kBins; ++i) EXPECT_EQ(counts[i], 1) << i;
  EXPECT_EQ(counts.back(), 2);
  for (const int count : TrackingErrorPlot::histogram(values, 1.0, 1.0)) EXPECT_EQ(count, 0);
}

TEST(TrackingErrorPlotTest, WritesAPngOfTheRequestedWidth) {
  const std::string path = tempPng("run");
  TrackingErrorPlot(900).writePng(run(), path);
  cairo_surface_t* image = cairo_image_surface_create_from_png(path.c_str());
  ASSERT_EQ(cairo_surface_status(image), CAIRO_STATUS_SUCCESS);
  EXPECT_EQ(cairo_image_surface_get_width(image), 900);
  EXPECT_EQ(cairo_image_surface_get_height(image), 720);
  cairo_surface_destroy(image);
  // A run without any error (a straight line followed exactly) still plots.
  TrackingErrorPlotData exact = run();
  for (std::size_t i = 0; i < exact.t.size(); ++i) {
    exact.error[i] = exact.error_x[i] = exact.error_y[i] = 0.0;
  }
  EXPECT_NO_THROW(TrackingErrorPlot().writePng(exact, tempPng("exact")));
}

TEST(TrackingErrorPlotTest, RejectsInvalidInput) {
  EXPECT_THROW(TrackingErrorPlot(100), InvalidInputError);
  const TrackingErrorPlot plot;
  EXPECT_THROW(plot.writePng(TrackingErrorPlotData{}, tempPng("empty")), InvalidInputError);
  TrackingErrorPlotData short_series = run();
  short_series.error_y.pop_back();
  EXPECT_THROW(plot.writePng(short_series, tempPng("short")), InvalidInputError);
  TrackingErrorPlotData not_finite = run();
  not_finite.error_x[3] = std::nan("");
  EXPECT_THROW(plot.writePng(not_finite, tempPng("nan")), InvalidInputError);
  TrackingErrorPlotData negative = run();
  negative.error[3] = -0.1;
  EXPECT_THROW(plot.writePng(negative, tempPng("negative")), InvalidInputError);
  TrackingErrorPlotData backwards = run();
  backwards.t[3] = 0.0;
  EXPECT_THROW(plot.writePng(backwards, tempPng("backwards")), InvalidInputError);
  try {
    plot.writePng(run(), "/nonexistent/dir/errors.png");
    FAIL() << "expected InvalidInputError";
  } catch (const InvalidInputError& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/dir/errors.png"), std::string::npos);
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
