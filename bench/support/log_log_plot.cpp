#include "bench/support/log_log_plot.h"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace kinematic_coverage::bench {
namespace {

constexpr int kWidth = 820;
constexpr int kHeight = 560;
constexpr double kLeft = 90.0;
constexpr double kRight = 30.0;
constexpr double kTop = 50.0;
constexpr double kBottom = 70.0;

/// "0.1", "1", "10", "1000": the value of a decade.
std::string decadeLabel(int exponent) {
  std::ostringstream text;
  text << std::pow(10.0, exponent);
  return text.str();
}

/// The decades [low, high] holding every positive value of `values` (at least one decade).
std::pair<int, int> decades(const std::vector<double>& values) {
  double low = std::numeric_limits<double>::infinity();
  double high = 0.0;
  for (const double v : values) {
    if (v <= 0.0) continue;
    low = std::min(low, v);
    high = std::max(high, v);
  }
  if (high <= 0.0) return {0, 1};
  const int first = static_cast<int>(std::floor(std::log10(low)));
  const int last = std::max(first + 1, static_cast<int>(std::ceil(std::log10(high))));
  return {first, last};
}

}  // namespace

double growthExponent(const std::vector<std::pair<double, double>>& points) {
  double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (const auto& [x, y] : points) {
    if (x <= 0.0 || y <= 0.0) continue;
    const double lx = std::log(x);
    const double ly = std::log(y);
    n += 1.0;
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
  }
  const double spread = n * sxx - sx * sx;
  if (n < 2.0 || spread <= 1e-12 * std::max(1.0, n * sxx)) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return (n * sxy - sx * sy) / spread;
}

void writeLogLogPlot(const std::string& path, const std::string& title, const std::string& x_title,
                     const std::string& y_title, const std::vector<LogLogSeries>& series) {
  std::vector<double> xs;
  std::vector<double> ys;
  for (const LogLogSeries& s : series) {
    for (const auto& [x, y] : s.points) {
      if (x > 0.0 && y > 0.0) xs.push_back(x), ys.push_back(y);
    }
  }
  const auto [x_low, x_high] = decades(xs);
  const auto [y_low, y_high] = decades(ys);
  const double plot_width = kWidth - kLeft - kRight;
  const double plot_height = kHeight - kTop - kBottom;
  const auto px = [&](double x) {
    return kLeft + (std::log10(x) - x_low) / (x_high - x_low) * plot_width;
  };
  const auto py = [&](double y) {
    return kTop + plot_height - (std::log10(y) - y_low) / (y_high - y_low) * plot_height;
  };

  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, kWidth, kHeight);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, 13);
  const auto text = [&](double x, double y, const std::string& s, double align) {
    cairo_text_extents_t extents;
    cairo_text_extents(cr, s.c_str(), &extents);
    cairo_move_to(cr, x - align * extents.width, y);
    cairo_show_text(cr, s.c_str());
  };

  // Grid and decade labels.
  cairo_set_line_width(cr, 1.0);
  for (int k = x_low; k <= x_high; ++k) {
    const double x = px(std::pow(10.0, k));
    cairo_set_source_rgb(cr, 0.85, 0.85, 0.85);
    cairo_move_to(cr, x, kTop);
    cairo_line_to(cr, x, kTop + plot_height);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    text(x, kTop + plot_height + 18, decadeLabel(k), 0.5);
  }
  for (int k = y_low; k <= y_high; ++k) {
    const double y = py(std::pow(10.0, k));
    cairo_set_source_rgb(cr, 0.85, 0.85, 0.85);
    cairo_move_to(cr, kLeft, y);
    cairo_line_to(cr, kLeft + plot_width, y);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    text(kLeft - 8, y + 4, decadeLabel(k), 1.0);
  }
  cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
  cairo_rectangle(cr, kLeft, kTop, plot_width, plot_height);
  cairo_stroke(cr);
  text(kLeft + 0.5 * plot_width, kHeight - 22, x_title, 0.5);
  cairo_save(cr);
  cairo_translate(cr, 28, kTop + 0.5 * plot_height);
  cairo_rotate(cr, -M_PI / 2);
  text(0, 0, y_title, 0.5);
  cairo_restore(cr);
  cairo_set_font_size(cr, 16);
  text(0.5 * kWidth, 30, title, 0.5);
  cairo_set_font_size(cr, 13);

  // The series, with a legend at the top left.
  double legend_y = kTop + 20;
  for (const LogLogSeries& s : series) {
    cairo_set_source_rgb(cr, s.red, s.green, s.blue);
    cairo_set_line_width(cr, 2.0);
    bool first = true;
    for (const auto& [x, y] : s.points) {
      if (x <= 0.0 || y <= 0.0) continue;
      if (first) {
        cairo_move_to(cr, px(x), py(y));
      } else {
        cairo_line_to(cr, px(x), py(y));
      }
      first = false;
    }
    cairo_stroke(cr);
    for (const auto& [x, y] : s.points) {
      if (x <= 0.0 || y <= 0.0) continue;
      cairo_arc(cr, px(x), py(y), 4.0, 0.0, 2.0 * M_PI);
      cairo_fill(cr);
    }
    cairo_move_to(cr, kLeft + 14, legend_y - 4);
    cairo_line_to(cr, kLeft + 40, legend_y - 4);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    text(kLeft + 48, legend_y, s.label, 0.0);
    legend_y += 20;
  }

  const cairo_status_t status = cairo_surface_write_to_png(surface, path.c_str());
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error("cannot write the plot " + path + ": " +
                             cairo_status_to_string(status));
  }
}

}  // namespace kinematic_coverage::bench
