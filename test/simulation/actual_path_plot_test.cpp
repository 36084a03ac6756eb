// The actual path of `coverage_tool simulate` in CoveragePlot: coloured by tracking error,
// with its colour bar (simulate's plot.png; docs/REFERENCE.md, coverage_tool).
#include <cairo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "trajectory_generation_tools/plot/coverage_plot.h"

namespace kinematic_coverage::core {
namespace {

/// A 30 x 20 m area and an actual path along y = 5 whose first half has no error and whose
/// second half has half the largest error; the largest error is at its end.
CoveragePlotData scene() {
  CoveragePlotData data;
  data.free_area.hull = {{0, 0}, {30, 0}, {30, 20}, {0, 20}};
  data.actual_path = {{5, 5, 0}, {15, 5, 0}, {25, 5, 0}};
  data.actual_errors = {0.0, 0.0, 1.0};
  return data;
}

/// Colour of the pixel containing image point `pixel` of a PNG file.
PlotColour colourAt(const std::string& path, const Point2& pixel) {
  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
      cairo_image_surface_create_from_png(path.c_str()), &cairo_surface_destroy);
  EXPECT_EQ(cairo_surface_status(surface.get()), CAIRO_STATUS_SUCCESS);
  const unsigned char* row =
      cairo_image_surface_get_data(surface.get()) +
      static_cast<int>(std::floor(pixel.y())) * cairo_image_surface_get_stride(surface.get());
  const std::uint32_t value =
      reinterpret_cast<const std::uint32_t*>(row)[static_cast<int>(std::floor(pixel.x()))];
  return {static_cast<std::uint8_t>(value >> 16), static_cast<std::uint8_t>(value >> 8),
          static_cast<std::uint8_t>(value)};
}

void expectColour(const PlotColour& expected, const PlotColour& actual, const std::string& what) {
  EXPECT_EQ(expected.red, actual.red) << what;
  EXPECT_EQ(expected.green, actual.green) << what;
  EXPECT_EQ(expected.blue, actual.blue) << what;
}

TEST(ActualPathPlotTest, PiecesAreColouredByTheirTrackingError) {
  const CoveragePlot plot(CoveragePlotOptions{900, 700});
  const CoveragePlotData data = scene();
  const std::string path = ::testing::TempDir() + "actual_path_plot.png";
  std::remove(path.c_str());
  plot.writePng(data, path);
  const CoveragePlotLayout layout = plot.layout(data);
  expectColour(CoveragePlot::errorColour(0.0), colourAt(path, layout.toPixel(Point2(10, 5))),
               "piece without error");
  expectColour(CoveragePlot::errorColour(0.5), colourAt(path, layout.toPixel(Point2(20, 5))),
               "piece at half the largest error");
  expectColour(kFreeAreaColour, colourAt(path, layout.toPixel(Point2(10, 12))), "off the path");

  // Millimetre errors stay dark: the colour scale reaches at least 5 cm.
  CoveragePlotData small = scene();
  small.actual_errors = {0.0, 0.0, 0.002};
  plot.writePng(small, path);
  expectColour(CoveragePlot::errorColour(0.001 / 0.05),
               colourAt(path, plot.layout(small).toPixel(Point2(20, 5))), "millimetre error");
}

TEST(ActualPathPlotTest, TheLayoutMakesRoomForAnActualPathOutsideTheHull) {
  const CoveragePlot plot;
  CoveragePlotData data = scene();
  data.actual_path.push_back({38, 26, 0});
  data.actual_errors.push_back(2.0);
  const CoveragePlotLayout layout = plot.layout(data);
  const Point2 p = layout.toPixel(Point2(38, 26));
  EXPECT_GT(p.x(), layout.box_left);
  EXPECT_LT(p.x(), layout.box_left + layout.box_width);
  EXPECT_GT(p.y(), layout.box_top);
  EXPECT_LT(p.y(), layout.box_top + layout.box_height);
}

TEST(ActualPathPlotTest, ErrorColoursRunThroughPlasmaAndClamp) {
  expectColour({13, 8, 135}, CoveragePlot::errorColour(0.0), "no error");
  expectColour({240, 249, 33}, CoveragePlot::errorColour(1.0), "largest error");
  expectColour({204, 71, 120}, CoveragePlot::errorColour(0.5), "half");
  expectColour(CoveragePlot::errorColour(0.0), CoveragePlot::errorColour(-3.0), "below 0");
  expectColour(CoveragePlot::errorColour(1.0), CoveragePlot::errorColour(7.0), "above 1");
  expectColour(CoveragePlot::errorColour(0.0), CoveragePlot::errorColour(std::nan("")), "NaN");
  // Brighter with the error (relative luminance), so that larger errors stand out.
  const auto luminance = [](const PlotColour& c) {
    return 0.2126 * c.red + 0.7152 * c.green + 0.0722 * c.blue;
  };
  for (int i = 1; i <= 10; ++i) {
    EXPECT_GT(luminance(CoveragePlot::errorColour(i / 10.0)),
              luminance(CoveragePlot::errorColour((i - 1) / 10.0)))
        << i;
  }
}

TEST(ActualPathPlotTest, RejectsErrorsThatDoNotMatchThePath) {
  const CoveragePlot plot;
  const std::string path = ::testing::TempDir() + "actual_path_invalid.png";
  CoveragePlotData missing = scene();
  missing.actual_errors.pop_back();
  EXPECT_THROW(plot.writePng(missing, path), InvalidInputError);
  CoveragePlotData negative = scene();
  negative.actual_errors[1] = -0.1;
  EXPECT_THROW(plot.writePng(negative, path), InvalidInputError);
  CoveragePlotData non_finite = scene();
  non_finite.actual_path[1].y = std::nan("");
  EXPECT_THROW(plot.writePng(non_finite, path), InvalidInputError);
}

}  // namespace
}  // namespace kinematic_coverage::core
