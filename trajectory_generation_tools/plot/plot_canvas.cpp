#include "trajectory_generation_tools/plot/plot_canvas.h"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {
namespace {

/// Image width at which fonts, margins and line widths have their nominal size.
constexpr double kNominalWidth = 1200.0;

}  // namespace

PlotScale plotScaleFor(int width) {
  const double f = std::sqrt(width / kNominalWidth);
  return {f, 21.0 * f, 15.0 * f, 14.0 * f, 15.0 * f, 14.0 * f};
}

void PlotCanvas::SurfaceDeleter::operator()(cairo_surface_t* surface) const {
  cairo_surface_destroy(surface);
}

void PlotCanvas::ContextDeleter::operator()(cairo_t* context) const { cairo_destroy(context); }

PlotCanvas::PlotCanvas(int width, int height, const std::string& what)
    : surface_(cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height)),
      context_(cairo_create(surface_.get())) {
  if (cairo_status(context_.get()) != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(what + ": cannot allocate a " + std::to_string(width) + " x " +
                             std::to_string(height) + " image");
  }
  setColour(context_.get(), kBackgroundColour);
  cairo_paint(context_.get());
}

void PlotCanvas::writePng(const std::string& path, const std::string& what) const {
  cairo_surface_flush(surface_.get());
  const cairo_status_t status = cairo_surface_write_to_png(surface_.get(), path.c_str());
  if (status != CAIRO_STATUS_SUCCESS) {
    throw InvalidInputError(what + ": cannot write '" + path +
                            "': " + cairo_status_to_string(status));
  }
}

void setColour(cairo_t* cr, const PlotColour& colour) {
  cairo_set_source_rgb(cr, colour.red / 255.0, colour.green / 255.0, colour.blue / 255.0);
}

void setColour(cairo_t* cr, const PlotColour& colour, double opacity) {
  cairo_set_source_rgba(cr, colour.red / 255.0, colour.green / 255.0, colour.blue / 255.0, opacity);
}

void selectFont(cairo_t* cr, double size, bool bold) {
  cairo_select_font_face(cr, "sans", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

void moveToText(cairo_t* cr, const std::string& text, double x, double y, TextAlign horizontal) {
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  cairo_font_extents_t font;
  cairo_font_extents(cr, &font);
  double left = x - extents.x_bearing;
  if (horizontal == TextAlign::kCentre) left -= 0.5 * extents.width;
  if (horizontal == TextAlign::kEnd) left -= extents.width;
  cairo_move_to(cr, left, y + 0.5 * (font.ascent - font.descent));
}

void showText(cairo_t* cr, const std::string& text, double x, double y, TextAlign horizontal) {
  moveToText(cr, text, x, y, horizontal);
  cairo_show_text(cr, text.c_str());
}

double niceStep(double range, double target_count) {
  const double raw = range / std::max(target_count, 1.0);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double best = magnitude;
  for (const double multiple : {2.0, 5.0, 10.0}) {
    const double step = multiple * magnitude;
    if (std::abs(std::log(step / raw)) < std::abs(std::log(best / raw))) best = step;
  }
  return best;
}

std::vector<double> ticks(double min, double max, double step) {
  std::vector<double> values;
  for (double k = std::ceil(min / step - 1e-9); k * step <= max + 1e-9 * step; k += 1.0) {
    values.push_back(k * step);
  }
  return values;
}

std::string tickLabel(double value, double step) {
  const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  if (std::abs(value) < 1e-9 * step) value = 0.0;
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", decimals, value);
  return text;
}

}  // namespace kinematic_coverage::core
