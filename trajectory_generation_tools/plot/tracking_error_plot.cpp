#include "trajectory_generation_tools/plot/tracking_error_plot.h"

#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <utility>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "trajectory_generation_tools/plot/plot_canvas.h"

namespace kinematic_coverage::core {
namespace {

constexpr int kMaxWidth = 4096;
constexpr PlotColour kEuclideanColour{20, 20, 20};
constexpr PlotColour kEuclideanBarColour{180, 180, 190};
constexpr PlotColour kXColour{33, 102, 172};
constexpr PlotColour kYColour{230, 97, 1};
/// On-image distance between axis ticks the tick step aims at, pixels.
constexpr double kTickSpacingPixels = 90.0;

/// A plotting box and the data range it shows.
struct Panel {
  double left = 0.0;  ///< pixels
  double top = 0.0;
  double width = 1.0;
  double height = 1.0;
  double x_min = 0.0;
  double x_max = 1.0;
  double y_min = 0.0;
  double y_max = 1.0;

  Point2 toPixel(double x, double y) const {
    return {left + (x - x_min) / (x_max - x_min) * width,
            top + height - (y - y_min) / (y_max - y_min) * height};
  }
};

/// A series drawn in a panel and named in its key.
struct KeyEntry {
  std::string name;
  PlotColour colour;
};

void checkData(const TrackingErrorPlotData& data) {
  const std::size_t n = data.t.size();
  if (n == 0) throw InvalidInputError("tracking error plot: no steps to plot");
  if (data.error.size() != n || data.error_x.size() != n || data.error_y.size() != n) {
    throw InvalidInputError("tracking error plot: the series must have one value per step");
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(data.t[i]) || !std::isfinite(data.error[i]) ||
        !std::isfinite(data.error_x[i]) || !std::isfinite(data.error_y[i])) {
      throw InvalidInputError("tracking error plot: step " + std::to_string(i) +
                              " has a non-finite value");
    }
    if (data.error[i] < 0.0) {
      throw InvalidInputError("tracking error plot: step " + std::to_string(i) +
                              " has a negative error");
    }
    if (i > 0 && data.t[i] < data.t[i - 1]) {
      throw InvalidInputError("tracking error plot: the times decrease at step " +
                              std::to_string(i));
    }
  }
}

/// [low, high] around `values` (with `include_zero`, from 0 at most), never empty.
std::pair<double, double> rangeOf(const std::vector<double>& values, bool include_zero) {
  double low = *std::min_element(values.begin(), values.end());
  double high = *std::max_element(values.begin(), values.end());
  if (include_zero) low = std::min(low, 0.0);
  if (!(high - low > 1e-9)) {
    const double middle = 0.5 * (low + high);
    return {include_zero ? std::min(0.0, middle - 0.005) : middle - 0.005, middle + 0.005};
  }
  return {low, high};
}

void drawFrame(cairo_t* cr, const Panel& panel, const std::string& title,
               const std::string& x_label, const std::string& y_label, const PlotScale& scale) {
  const double f = scale.factor;
  const double tick_length = 5.0 * f;
  setColour(cr, kOutlineColour);
  cairo_set_line_width(cr, 1.1 * f);
  cairo_rectangle(cr, panel.left, panel.top, panel.width, panel.height);
  cairo_stroke(cr);
  selectFont(cr, scale.tick, false);
  const double x_step = niceStep(panel.x_max - panel.x_min, panel.width / (kTickSpacingPixels * f));
  for (const double x : ticks(panel.x_min, panel.x_max, x_step)) {
    const double px = panel.toPixel(x, panel.y_min).x();
    cairo_move_to(cr, px, panel.top + panel.height);
    cairo_line_to(cr, px, panel.top + panel.height + tick_length);
    showText(cr, tickLabel(x, x_step), px,
             panel.top + panel.height + tick_length + 0.85 * scale.tick, TextAlign::kCentre);
  }
  const double y_step =
      niceStep(panel.y_max - panel.y_min, panel.height / (0.7 * kTickSpacingPixels * f));
  for (const double y : ticks(panel.y_min, panel.y_max, y_step)) {
    const double py = panel.toPixel(panel.x_min, y).y();
    cairo_move_to(cr, panel.left, py);
    cairo_line_to(cr, panel.left - tick_length, py);
    showText(cr, tickLabel(y, y_step), panel.left - tick_length - 3.0 * f, py, TextAlign::kEnd);
  }
  cairo_stroke(cr);
  selectFont(cr, scale.label, false);
  showText(cr, x_label, panel.left + 0.5 * panel.width,
           panel.top + panel.height + tick_length + 2.3 * scale.label, TextAlign::kCentre);
  cairo_save(cr);
  cairo_translate(cr, panel.left - tick_length - 4.0 * scale.label, panel.top + 0.5 * panel.height);
  cairo_rotate(cr, -0.5 * M_PI);
  showText(cr, y_label, 0.0, 0.0, TextAlign::kCentre);
  cairo_restore(cr);
  selectFont(cr, scale.label, true);
  setColour(cr, kTextColour);
  showText(cr, title, panel.left, panel.top - 0.9 * scale.label, TextAlign::kStart);
}

/// The polyline through the points (xs[i], ys[i]) of the panel, as the current path.
void polylinePath(cairo_t* cr, const Panel& panel, const std::vector<double>& xs,
                  const std::vector<double>& ys) {
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const Point2 p = panel.toPixel(xs[i], ys[i]);
    if (i == 0) {
      cairo_move_to(cr, p.x(), p.y());
    } else {
      cairo_line_to(cr, p.x(), p.y());
    }
  }
}

/// The histogram of `values` over [panel.x_min, panel.x_max] as a density: filled bars, or
/// a step outline.
void drawHistogram(cairo_t* cr, const Panel& panel, const std::vector<double>& values,
                   const PlotColour& colour, bool filled, const PlotScale& scale) {
  const std::vector<int> counts = TrackingErrorPlot::histogram(values, panel.x_min, panel.x_max);
  const double bin = (panel.x_max - panel.x_min) / TrackingErrorPlot::kBins;
  const double per_value = 1.0 / (static_cast<double>(values.size()) * bin);
  setColour(cr, colour);
  cairo_set_line_width(cr, 1.6 * scale.factor);
  for (int b = 0; b < TrackingErrorPlot::kBins; ++b) {
    const Point2 low = panel.toPixel(panel.x_min + b * bin, 0.0);
    const Point2 high = panel.toPixel(panel.x_min + (b + 1) * bin, counts[b] * per_value);
    if (filled) {
      cairo_rectangle(cr, low.x(), high.y(), high.x() - low.x(), low.y() - high.y());
    } else {
      if (b == 0) cairo_move_to(cr, low.x(), low.y());
      cairo_line_to(cr, low.x(), high.y());
      cairo_line_to(cr, high.x(), high.y());
      if (b + 1 == TrackingErrorPlot::kBins) cairo_line_to(cr, high.x(), low.y());
    }
  }
  if (filled) {
    cairo_fill(cr);
  } else {
    cairo_stroke(cr);
  }
}

/// The density of `fit` over the panel's x range; nothing for a zero deviation.
void drawNormal(cairo_t* cr, const Panel& panel, const NormalFit& fit, const PlotColour& colour,
                const PlotScale& scale) {
  if (!(fit.standard_deviation > 0.0)) return;
  constexpr int kPoints = 200;
  cairo_save(cr);
  cairo_rectangle(cr, panel.left, panel.top, panel.width, panel.height);
  cairo_clip(cr);
  std::vector<double> xs;
  std::vector<double> densities;
  for (int i = 0; i <= kPoints; ++i) {
    const double x = panel.x_min + (panel.x_max - panel.x_min) * i / kPoints;
    const double z = (x - fit.mean) / fit.standard_deviation;
    xs.push_back(x);
    densities.push_back(std::exp(-0.5 * z * z) / (fit.standard_deviation * std::sqrt(2 * M_PI)));
  }
  polylinePath(cr, panel, xs, densities);
  setColour(cr, colour);
  cairo_set_line_width(cr, 2.2 * scale.factor);
  cairo_set_dash(cr, std::array<double, 2>{7.0 * scale.factor, 4.0 * scale.factor}.data(), 2, 0.0);
  cairo_stroke(cr);
  cairo_restore(cr);
}

/// `values` over `t` as a polyline.
void drawSeries(cairo_t* cr, const Panel& panel, const std::vector<double>& t,
                const std::vector<double>& values, const PlotColour& colour,
                const PlotScale& scale) {
  polylinePath(cr, panel, t, values);
  setColour(cr, colour);
  cairo_set_line_width(cr, 1.3 * scale.factor);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_stroke(cr);
}

/// A key in the panel's top-right corner.
void drawKey(cairo_t* cr, const Panel& panel, const std::vector<KeyEntry>& entries,
             const PlotScale& scale) {
  const double f = scale.factor;
  selectFont(cr, scale.legend, false);
  double widest = 0.0;
  for (const KeyEntry& entry : entries) {
    cairo_text_extents_t extents;
    cairo_text_extents(cr, entry.name.c_str(), &extents);
    widest = std::max(widest, extents.width);
  }
  double y = panel.top + 14.0 * f;
  const double right = panel.left + panel.width - 10.0 * f;
  cairo_rectangle(cr, right - 40.0 * f - widest, panel.top + 4.0 * f, widest + 46.0 * f,
                  1.5 * scale.legend * static_cast<double>(entries.size()) + 4.0 * f);
  cairo_set_source_rgba(cr, 1.0, 1.0, 1.0, 0.85);
  cairo_fill(cr);
  for (const KeyEntry& entry : entries) {
    setColour(cr, entry.colour);
    cairo_set_line_width(cr, 3.0 * f);
    cairo_move_to(cr, right - 26.0 * f, y);
    cairo_line_to(cr, right, y);
    cairo_stroke(cr);
    setColour(cr, kTextColour);
    showText(cr, entry.name, right - 32.0 * f, y, TextAlign::kEnd);
    y += 1.5 * scale.legend;
  }
}

std::string fitName(const std::string& what, const NormalFit& fit) {
  char text[128];
  std::snprintf(text, sizeof(text), "%s: normal fit, mean %.3f m, sd %.3f m", what.c_str(),
                fit.mean, fit.standard_deviation);
  return text;
}

/// The largest density the histograms and fits of `series` reach over [low, high].
double densityTop(const std::vector<const std::vector<double>*>& series, double low, double high) {
  double top = 0.0;
  const double bin = (high - low) / TrackingErrorPlot::kBins;
  for (const std::vector<double>* values : series) {
    const std::vector<int> counts = TrackingErrorPlot::histogram(*values, low, high);
    const int most = *std::max_element(counts.begin(), counts.end());
    top = std::max(top, most / (static_cast<double>(values->size()) * bin));
    const NormalFit fit = TrackingErrorPlot::fit(*values);
    if (fit.standard_deviation > 0.0) {
      top = std::max(top, 1.0 / (fit.standard_deviation * std::sqrt(2 * M_PI)));
    }
  }
  return 1.05 * std::max(top, 1e-9);
}

}  // namespace

TrackingErrorPlot::TrackingErrorPlot(int width) : width_(width) {
  if (width < CoveragePlotOptions::kMinSide || width > kMaxWidth) {
    throw InvalidInputError(
        "tracking error plot: width " + std::to_string(width) + " pixels, it must be in [" +
        std::to_string(CoveragePlotOptions::kMinSide) + ", " + std::to_string(kMaxWidth) + "]");
  }
}

NormalFit TrackingErrorPlot::fit(const std::vector<double>& values) {
  NormalFit fit;
  if (values.empty()) return fit;
  const double n = static_cast<double>(values.size());
  fit.mean = std::accumulate(values.begin(), values.end(), 0.0) / n;
  double squares = 0.0;
  for (const double value : values) squares += (value - fit.mean) * (value - fit.mean);
  fit.standard_deviation = std::sqrt(squares / n);
  return fit;
}

std::vector<int> TrackingErrorPlot::histogram(const std::vector<double>& values, double low,
                                              double high) {
  std::vector<int> counts(kBins, 0);
  if (!(high > low)) return counts;
  for (const double value : values) {
    if (value < low || value > high) continue;
    const int bin = std::min(kBins - 1, static_cast<int>((value - low) / (high - low) * kBins));
    ++counts[bin];
  }
  return counts;
}

void TrackingErrorPlot::writePng(const TrackingErrorPlotData& data, const std::string& path) const {
  checkData(data);
  const PlotScale scale = plotScaleFor(width_);
  const double f = scale.factor;
  const int height = static_cast<int>(std::lround(0.8 * width_));
  const PlotCanvas canvas(width_, height, "tracking error plot");
  cairo_t* cr = canvas.context();

  double y = 16.0 * f + 0.6 * scale.title;
  for (std::size_t i = 0; i < data.title_lines.size(); ++i) {
    selectFont(cr, i == 0 ? scale.title : scale.subtitle, i == 0);
    setColour(cr, i == 0 ? kTextColour : kSubtitleColour);
    showText(cr, data.title_lines[i], 0.5 * width_, y, TextAlign::kCentre);
    y += 1.35 * (i == 0 ? 0.5 * (scale.title + scale.subtitle) : scale.subtitle);
  }
  const double left = 80.0 * f;
  const double gap = 90.0 * f;
  const double top = y + 34.0 * f;
  const double panel_width = 0.5 * (width_ - left - gap - 24.0 * f);
  const double row_gap = 90.0 * f;
  const double row_height = 0.5 * (height - top - row_gap - 64.0 * f);

  const auto [error_low, error_high] = rangeOf(data.error, true);
  Panel euclidean{left, top, panel_width, row_height, error_low, error_high, 0.0, 1.0};
  euclidean.y_max = densityTop({&data.error}, error_low, error_high);
  drawHistogram(cr, euclidean, data.error, kEuclideanBarColour, true, scale);
  const NormalFit error_fit = fit(data.error);
  drawNormal(cr, euclidean, error_fit, kEuclideanColour, scale);
  drawFrame(cr, euclidean, "Error histogram and normal fit", "error [m]", "density [1/m]", scale);
  drawKey(cr, euclidean, {{fitName("error", error_fit), kEuclideanColour}}, scale);

  const auto [x_low, x_high] = rangeOf(data.error_x, false);
  const auto [y_low, y_high] = rangeOf(data.error_y, false);
  const double reach =
      std::max({std::abs(x_low), std::abs(x_high), std::abs(y_low), std::abs(y_high)});
  Panel axes{left + panel_width + gap, top, panel_width, row_height, -reach, reach, 0.0, 1.0};
  axes.y_max = densityTop({&data.error_x, &data.error_y}, -reach, reach);
  drawHistogram(cr, axes, data.error_x, kXColour, false, scale);
  drawHistogram(cr, axes, data.error_y, kYColour, false, scale);
  const NormalFit x_fit = fit(data.error_x);
  const NormalFit y_fit = fit(data.error_y);
  drawNormal(cr, axes, x_fit, kXColour, scale);
  drawNormal(cr, axes, y_fit, kYColour, scale);
  drawFrame(cr, axes, "x and y parts of the error", "error [m]", "density [1/m]", scale);
  drawKey(cr, axes, {{fitName("x", x_fit), kXColour}, {fitName("y", y_fit), kYColour}}, scale);

  const auto [signed_low, signed_high] =
      rangeOf({std::min({x_low, y_low, 0.0}), std::max({x_high, y_high, error_high})}, false);
  const auto [t_low, t_high] = rangeOf(data.t, false);
  const Panel over_time{left,
                        top + row_height + row_gap,
                        2.0 * panel_width + gap,
                        row_height,
                        t_low,
                        t_high,
                        signed_low,
                        signed_high};
  cairo_save(cr);
  cairo_rectangle(cr, over_time.left, over_time.top, over_time.width, over_time.height);
  cairo_clip(cr);
  drawSeries(cr, over_time, data.t, data.error_x, kXColour, scale);
  drawSeries(cr, over_time, data.t, data.error_y, kYColour, scale);
  drawSeries(cr, over_time, data.t, data.error, kEuclideanColour, scale);
  cairo_restore(cr);
  drawFrame(cr, over_time, "Errors over time", "t [s]", "error [m]", scale);
  drawKey(cr, over_time, {{"x", kXColour}, {"y", kYColour}, {"Euclidean", kEuclideanColour}},
          scale);
  canvas.writePng(path, "tracking error plot");
}

}  // namespace kinematic_coverage::core
