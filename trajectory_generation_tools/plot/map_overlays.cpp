#include "trajectory_generation_tools/plot/map_overlays.h"

#include <cairo.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// The scale bar aims at this share of the box width.
constexpr double kScaleBarWidthShare = 1.0 / 5.0;
/// Metres from which the scale bar is labelled in kilometres.
constexpr double kMetresPerKilometre = 1000.0;
/// Opacity of the white backing of the scale bar and north arrow.
constexpr double kBackingOpacity = 0.78;
/// Sizes at the base image size, pixels: the overlays' distance from the box edges, the
/// free space around their content, the scale bar's line width and end tick height,
/// and the north arrow's half length and half width.
constexpr double kCornerInset = 8.0;
constexpr double kBackingPadding = 6.0;
constexpr double kScaleBarLineWidth = 2.0;
constexpr double kScaleBarTickHeight = 7.0;
constexpr double kNorthNeedleHalfLength = 11.0;
constexpr double kNorthNeedleHalfWidth = 4.0;
/// Samples per side of a corner when measuring how much free area it would hide.
constexpr int kCornerSamples = 6;
/// Pixels around the start and goal markers (with their labels) that an overlay keeps
/// clear of, at the base image size, and what covering one costs against hiding a
/// corner full of free area (cost 1).
constexpr double kMarkerClearance = 45.0;
constexpr double kMarkerCost = 4.0;

/// A rectangle on the image, pixels.
struct Rect {
  double left = 0.0;
  double top = 0.0;
  double width = 0.0;
  double height = 0.0;

  bool contains(const Point2& p, double margin = 0.0) const {
    return p.x() >= left - margin && p.x() <= left + width + margin && p.y() >= top - margin &&
           p.y() <= top + height + margin;
  }
};

/// The box's corners, in the order the scale bar prefers them and in the north arrow's.
enum class Corner { kBottomLeft, kBottomRight, kTopLeft, kTopRight };
constexpr std::array<Corner, 4> kScaleBarCorners{Corner::kBottomLeft, Corner::kBottomRight,
                                                 Corner::kTopLeft, Corner::kTopRight};
constexpr std::array<Corner, 4> kNorthArrowCorners{Corner::kTopRight, Corner::kTopLeft,
                                                   Corner::kBottomRight, Corner::kBottomLeft};

Rect cornerRect(const CoveragePlotLayout& layout, Corner corner, double width, double height,
                double inset) {
  const bool left = corner == Corner::kBottomLeft || corner == Corner::kTopLeft;
  const bool top = corner == Corner::kTopLeft || corner == Corner::kTopRight;
  return {left ? layout.box_left + inset : layout.box_left + layout.box_width - inset - width,
          top ? layout.box_top + inset : layout.box_top + layout.box_height - inset - height, width,
          height};
}

/// How much an overlay at `rect` would hide: the share of it over the free area, the
/// on-image length of the paths under it per pixel of its width and height, and the
/// start and goal markers near it.
double hiddenCost(const Rect& rect, const CoveragePlotLayout& layout, const CoveragePlotData& data,
                  const PlotScale& scale) {
  double free_samples = 0.0;
  const double metres_per_pixel = 1.0 / layout.pixels_per_metre;
  for (int i = 0; i < kCornerSamples; ++i) {
    for (int j = 0; j < kCornerSamples; ++j) {
      const double x = rect.left + (i + 0.5) * rect.width / kCornerSamples - layout.box_left;
      const double y =
          layout.box_top + layout.box_height - rect.top - (j + 0.5) * rect.height / kCornerSamples;
      const Point2 world = layout.box_world_min + Point2(x, y) * metres_per_pixel;
      if (contains(data.free_area, world)) free_samples += 1.0;
    }
  }
  double cost = free_samples / (kCornerSamples * kCornerSamples);
  double path_pixels = 0.0;
  for (const std::vector<Pose2>* path : {&data.trajectory, &data.waypoints}) {
    for (std::size_t i = 1; i < path->size(); ++i) {
      const Point2 a = layout.toPixel((*path)[i - 1].position());
      const Point2 b = layout.toPixel((*path)[i].position());
      if (rect.contains(0.5 * (a + b))) path_pixels += (b - a).norm();
    }
  }
  cost += path_pixels / (rect.width + rect.height);
  for (const std::optional<Point2>& marker : {data.start, data.goal}) {
    if (marker && rect.contains(layout.toPixel(*marker), kMarkerClearance * scale.factor)) {
      cost += kMarkerCost;
    }
  }
  return cost;
}

/// The corner, other than `taken`, where an overlay of `width` x `height` pixels hides the
/// least; ties go to the earlier corner in `order`.
Corner bestCorner(const CoveragePlotLayout& layout, const CoveragePlotData& data,
                  const PlotScale& scale, double width, double height,
                  const std::array<Corner, 4>& order, std::optional<Corner> taken) {
  Corner best = order.front();
  double best_cost = std::numeric_limits<double>::infinity();
  for (const Corner corner : order) {
    if (taken && *taken == corner) continue;
    const double cost =
        hiddenCost(cornerRect(layout, corner, width, height, kCornerInset * scale.factor), layout,
                   data, scale);
    if (cost < best_cost) {
      best_cost = cost;
      best = corner;
    }
  }
  return best;
}

void fillBacking(cairo_t* cr) {
  cairo_set_source_rgba(cr, 1.0, 1.0, 1.0, kBackingOpacity);
  cairo_fill(cr);
}

/// The scale bar's size on the image, pixels, for a bar `bar_pixels` long.
Point2 scaleBarSize(double bar_pixels, const PlotScale& scale) {
  const double f = scale.factor;
  return {bar_pixels + 2.0 * kBackingPadding * f,
          2.0 * kBackingPadding * f + 1.2 * scale.legend + kScaleBarTickHeight * f};
}

/// A bar `bar_pixels` long with end ticks, its label above it, on a backing filling `rect`.
void drawScaleBar(cairo_t* cr, const Rect& rect, double bar_pixels, const std::string& label,
                  const PlotScale& scale) {
  const double f = scale.factor;
  cairo_rectangle(cr, rect.left, rect.top, rect.width, rect.height);
  fillBacking(cr);
  const double left = rect.left + kBackingPadding * f;
  const double bar_y = rect.top + rect.height - kBackingPadding * f;
  const double tick_top = bar_y - kScaleBarTickHeight * f;
  setColour(cr, kTextColour);
  cairo_set_line_width(cr, kScaleBarLineWidth * f);
  cairo_move_to(cr, left, tick_top);
  cairo_line_to(cr, left, bar_y);
  cairo_line_to(cr, left + bar_pixels, bar_y);
  cairo_line_to(cr, left + bar_pixels, tick_top);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
  cairo_stroke(cr);
  selectFont(cr, scale.legend, false);
  showText(cr, label, left + 0.5 * bar_pixels, tick_top - 0.6 * scale.legend, TextAlign::kCentre);
}

/// The north arrow's backing radius, pixels.
double northArrowRadius(const PlotScale& scale) {
  return kNorthNeedleHalfLength * scale.factor + 1.3 * scale.legend;
}

/// A compass needle through the centre of `rect`, its dark half and an "N" towards north
/// (`north` radians counter-clockwise from +x in the world), on a round backing.
void drawNorthArrow(cairo_t* cr, const Rect& rect, double north, const PlotScale& scale) {
  const double f = scale.factor;
  const Point2 centre(rect.left + 0.5 * rect.width, rect.top + 0.5 * rect.height);
  cairo_new_sub_path(cr);
  cairo_arc(cr, centre.x(), centre.y(), northArrowRadius(scale), 0.0, 2.0 * M_PI);
  fillBacking(cr);
  const Point2 along(std::cos(north), -std::sin(north));
  const Point2 across(-along.y(), along.x());
  const Point2 tip = centre + kNorthNeedleHalfLength * f * along;
  const Point2 tail = centre - kNorthNeedleHalfLength * f * along;
  const Point2 side_a = centre + kNorthNeedleHalfWidth * f * across;
  const Point2 side_b = centre - kNorthNeedleHalfWidth * f * across;
  cairo_move_to(cr, tip.x(), tip.y());
  cairo_line_to(cr, side_a.x(), side_a.y());
  cairo_line_to(cr, side_b.x(), side_b.y());
  cairo_close_path(cr);
  setColour(cr, kTextColour);
  cairo_fill(cr);
  cairo_move_to(cr, tail.x(), tail.y());
  cairo_line_to(cr, side_a.x(), side_a.y());
  cairo_line_to(cr, side_b.x(), side_b.y());
  cairo_close_path(cr);
  cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
  cairo_fill_preserve(cr);
  setColour(cr, kTextColour);
  cairo_set_line_width(cr, 1.0 * f);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
  cairo_stroke(cr);
  selectFont(cr, scale.legend, true);
  const Point2 label = centre + (kNorthNeedleHalfLength * f + 0.7 * scale.legend) * along;
  showText(cr, "N", label.x(), label.y(), TextAlign::kCentre);
}

}  // namespace

double CoveragePlot::scaleBarLength(double box_width_metres) {
  return niceStep(box_width_metres, 1.0 / kScaleBarWidthShare);
}

std::string CoveragePlot::scaleBarLabel(double length_metres) {
  char text[32];
  if (length_metres >= kMetresPerKilometre) {
    std::snprintf(text, sizeof(text), "%g km", length_metres / kMetresPerKilometre);
  } else {
    std::snprintf(text, sizeof(text), "%g m", length_metres);
  }
  return text;
}

void drawMapOverlays(cairo_t* cr, const CoveragePlotLayout& layout, const CoveragePlotData& data,
                     const PlotScale& scale) {
  const double inset = kCornerInset * scale.factor;
  const double length = CoveragePlot::scaleBarLength(layout.box_width / layout.pixels_per_metre);
  const double bar_pixels = length * layout.pixels_per_metre;
  const Point2 bar_size = scaleBarSize(bar_pixels, scale);
  const Corner bar_corner =
      bestCorner(layout, data, scale, bar_size.x(), bar_size.y(), kScaleBarCorners, std::nullopt);
  drawScaleBar(cr, cornerRect(layout, bar_corner, bar_size.x(), bar_size.y(), inset), bar_pixels,
               CoveragePlot::scaleBarLabel(length), scale);
  if (!data.north_direction) return;
  const double side = 2.0 * northArrowRadius(scale);
  const Corner north_corner =
      bestCorner(layout, data, scale, side, side, kNorthArrowCorners, bar_corner);
  drawNorthArrow(cr, cornerRect(layout, north_corner, side, side, inset), *data.north_direction,
                 scale);
}

}  // namespace kinematic_coverage::core
