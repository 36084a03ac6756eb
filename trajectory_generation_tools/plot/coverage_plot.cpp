#include "trajectory_generation_tools/plot/coverage_plot.h"

#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>
#include <tuple>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "trajectory_generation_tools/plot/map_overlays.h"
#include "trajectory_generation_tools/plot/path_style.h"
#include "trajectory_generation_tools/plot/plot_canvas.h"

namespace kinematic_coverage::core {
namespace {

/// Heatmap colours for 0, 1, 2, 3 and 4+ visits: red for never seen, then a light-to-dark
/// sequence (ColorBrewer YlGnBu) for seen once and for overlap.
constexpr std::array<PlotColour, 5> kVisitColours{
    {{215, 48, 39}, {199, 233, 180}, {127, 205, 187}, {65, 182, 196}, {44, 127, 184}}};
constexpr PlotColour kOffsetAreaColour{80, 80, 80};
constexpr PlotColour kWaypointColour{230, 97, 1};
constexpr PlotColour kTrajectoryColour{20, 20, 20};
/// The trajectory under the actual pose arrows, red as in the thesis's Fig. 4.3.
constexpr PlotColour kDesiredColour{215, 25, 28};
constexpr PlotColour kStartColour{26, 152, 80};
constexpr PlotColour kGoalColour{123, 50, 148};
constexpr PlotColour kUnseenRegionColour{200, 0, 110};
/// Pixels: the unseen region's outline stands this far outside it, and a region smaller
/// than kUnseenRegionMinPixels across is circled as well.
constexpr double kUnseenRegionMarginPixels = 4.0;
constexpr double kUnseenRegionMinPixels = 16.0;
/// The closest approach's cross: its arms' reach as a share of its circle's radius.
constexpr double kClosestApproachCrossShare = 0.7;
/// The "plasma" colour map at 0, 1/4, 1/2, 3/4 and 1, for the tracking error.
constexpr std::array<PlotColour, 5> kErrorColours{
    {{13, 8, 135}, {126, 3, 168}, {204, 71, 120}, {248, 149, 64}, {240, 249, 33}}};

/// The heatmap image's longest side, pixels: larger grids are sampled down in blocks, which
/// keeps memory bounded and is still finer than any plot box.
constexpr int kMaxHeatmapImageSide = 4096;
/// The actual pose arrows' size as a share of the nominal heading arrows'.
constexpr double kPoseArrowShare = 0.7;
/// Free margin around the drawn items, as a share of their larger extent.
constexpr double kBoundsPadding = 0.04;
/// Box height range, as a share of its width, when the image height follows the area.
constexpr double kMinAutoAspect = 0.45;
constexpr double kMaxAutoAspect = 1.4;
/// Least box size, pixels, that leaves room for the plot after the margins.
constexpr double kMinBoxSide = 100.0;
/// On-image distance between axis ticks the tick step aims at, pixels.
constexpr double kTickSpacingPixels = 110.0;

bool isFinite(const Point2& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }

void checkRing(const Ring& ring, const std::string& what) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (!isFinite(ring[i])) {
      throw InvalidInputError("coverage plot: non-finite vertex " + std::to_string(i) + " in " +
                              what);
    }
  }
}

void checkArea(const PolygonWithHoles& area, const std::string& what) {
  checkRing(area.hull, what + " hull");
  for (std::size_t h = 0; h < area.holes.size(); ++h) {
    checkRing(area.holes[h], what + " hole " + std::to_string(h));
  }
}

void checkPoses(const std::vector<Pose2>& poses, const std::string& what) {
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const Pose2& pose = poses[i];
    if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.yaw)) {
      throw InvalidInputError("coverage plot: non-finite pose " + std::to_string(i) + " in " +
                              what);
    }
  }
}

void checkHeatmap(const Heatmap& heatmap) {
  if (!isFinite(heatmap.origin) || !std::isfinite(heatmap.cell_size) || heatmap.cell_size <= 0.0) {
    throw InvalidInputError(
        "coverage plot: heatmap origin and cell size must be finite and the cell size > 0");
  }
  if (heatmap.columns <= 0 || heatmap.rows <= 0) {
    throw InvalidInputError("coverage plot: heatmap grid is empty (" +
                            std::to_string(heatmap.columns) + " x " + std::to_string(heatmap.rows) +
                            " cells)");
  }
  const std::size_t cells =
      static_cast<std::size_t>(heatmap.columns) * static_cast<std::size_t>(heatmap.rows);
  if (heatmap.visits.size() != cells) {
    throw InvalidInputError("coverage plot: heatmap has " + std::to_string(heatmap.visits.size()) +
                            " visit counts for " + std::to_string(cells) + " cells");
  }
}

void checkData(const CoveragePlotData& data) {
  if (data.free_area.hull.size() < 3) {
    throw InvalidInputError("coverage plot: free area hull has " +
                            std::to_string(data.free_area.hull.size()) +
                            " vertices, needs at least 3");
  }
  checkArea(data.free_area, "free area");
  const auto [min_x, max_x] =
      std::minmax_element(data.free_area.hull.begin(), data.free_area.hull.end(),
                          [](const Point2& a, const Point2& b) { return a.x() < b.x(); });
  const auto [min_y, max_y] =
      std::minmax_element(data.free_area.hull.begin(), data.free_area.hull.end(),
                          [](const Point2& a, const Point2& b) { return a.y() < b.y(); });
  if (!(max_x->x() > min_x->x()) || !(max_y->y() > min_y->y())) {
    throw InvalidInputError("coverage plot: free area hull has no extent in x or y");
  }
  for (const PolygonWithHoles& part : data.offset_parts) checkArea(part, "offset free area");
  for (const PolygonWithHoles& part : data.unreachable_parts) checkArea(part, "unreachable part");
  if (data.heatmap) checkHeatmap(*data.heatmap);
  checkPoses(data.waypoints, "waypoint path");
  checkPoses(data.trajectory, "trajectory");
  checkPoses(data.actual_path, "actual path");
  checkPoses(data.actual_pose_arrows, "actual pose arrows");
  if (data.actual_errors.size() != data.actual_path.size()) {
    throw InvalidInputError("coverage plot: " + std::to_string(data.actual_errors.size()) +
                            " actual errors for " + std::to_string(data.actual_path.size()) +
                            " actual poses");
  }
  for (std::size_t i = 0; i < data.actual_errors.size(); ++i) {
    if (!std::isfinite(data.actual_errors[i]) || data.actual_errors[i] < 0.0) {
      throw InvalidInputError("coverage plot: actual error " + std::to_string(i) +
                              " must be finite and >= 0");
    }
  }
  if (data.start && !isFinite(*data.start)) {
    throw InvalidInputError("coverage plot: non-finite start");
  }
  if (data.goal && !isFinite(*data.goal)) {
    throw InvalidInputError("coverage plot: non-finite goal");
  }
  if (data.closest_approach && !isFinite(*data.closest_approach)) {
    throw InvalidInputError("coverage plot: non-finite closest approach");
  }
  if (data.north_direction && !std::isfinite(*data.north_direction)) {
    throw InvalidInputError("coverage plot: non-finite north direction");
  }
}

/// Axis-aligned bounds of points.
struct Bounds {
  Point2 min = Point2::Constant(std::numeric_limits<double>::infinity());
  Point2 max = Point2::Constant(-std::numeric_limits<double>::infinity());

  void add(const Point2& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
};

/// Bounds of everything drawn in the box except the heatmap, which may reach beyond the
/// free area it is clipped to.
Bounds drawnBounds(const CoveragePlotData& data) {
  Bounds bounds;
  for (const Point2& p : data.free_area.hull) bounds.add(p);
  for (const PolygonWithHoles& part : data.offset_parts) {
    for (const Point2& p : part.hull) bounds.add(p);
  }
  for (const Pose2& pose : data.waypoints) bounds.add(pose.position());
  for (const Pose2& pose : data.trajectory) bounds.add(pose.position());
  for (const Pose2& pose : data.actual_path) bounds.add(pose.position());
  for (const Pose2& pose : data.actual_pose_arrows) bounds.add(pose.position());
  if (data.start) bounds.add(*data.start);
  if (data.goal) bounds.add(*data.goal);
  return bounds;
}

/// Height of the title block above the box, pixels.
double titleBlockHeight(const std::vector<std::string>& lines, const PlotScale& scale) {
  if (lines.empty()) return 26.0 * scale.factor;
  double height = 18.0 * scale.factor + 1.35 * scale.title;
  height += 1.35 * scale.subtitle * static_cast<double>(lines.size() - 1);
  return height + 16.0 * scale.factor;
}

CoveragePlotLayout computeLayout(const CoveragePlotData& data, const CoveragePlotOptions& options) {
  checkData(data);
  Bounds bounds = drawnBounds(data);
  const Point2 extent = bounds.max - bounds.min;
  const double padding = kBoundsPadding * extent.maxCoeff();
  bounds.min -= Point2::Constant(padding);
  bounds.max += Point2::Constant(padding);
  const Point2 span = bounds.max - bounds.min;
  if (!std::isfinite(span.x()) || !std::isfinite(span.y())) {
    throw InvalidInputError("coverage plot: coordinates too large to plot");
  }

  const PlotScale scale = plotScaleFor(options.width);
  CoveragePlotLayout layout;
  layout.width = options.width;
  layout.box_left = std::round(92.0 * scale.factor);
  layout.box_top = std::round(titleBlockHeight(data.title_lines, scale));
  layout.box_width = std::round(options.width - layout.box_left - 240.0 * scale.factor);
  const double bottom_margin = std::round(68.0 * scale.factor);
  if (options.height == 0) {
    const double aspect = std::clamp(span.y() / span.x(), kMinAutoAspect, kMaxAutoAspect);
    layout.box_height = std::round(layout.box_width * aspect);
    layout.height = static_cast<int>(layout.box_top + layout.box_height + bottom_margin);
    if (layout.height > CoveragePlotOptions::kMaxSide) {
      throw InvalidInputError("coverage plot: " + std::to_string(layout.height) +
                              " pixels high, more than " +
                              std::to_string(CoveragePlotOptions::kMaxSide));
    }
  } else {
    layout.height = options.height;
    layout.box_height = options.height - layout.box_top - bottom_margin;
  }
  if (layout.box_width < kMinBoxSide || layout.box_height < kMinBoxSide) {
    throw InvalidInputError("coverage plot: " + std::to_string(layout.width) + " x " +
                            std::to_string(layout.height) +
                            " pixels leave no room for the plot after the title and axes");
  }
  layout.pixels_per_metre = std::min(layout.box_width / span.x(), layout.box_height / span.y());
  const Point2 box_span = Point2(layout.box_width, layout.box_height) / layout.pixels_per_metre;
  layout.box_world_min = 0.5 * (bounds.min + bounds.max) - 0.5 * box_span;
  return layout;
}

void moveTo(cairo_t* cr, const CoveragePlotLayout& layout, const Point2& world) {
  const Point2 p = layout.toPixel(world);
  cairo_move_to(cr, p.x(), p.y());
}

void lineTo(cairo_t* cr, const CoveragePlotLayout& layout, const Point2& world) {
  const Point2 p = layout.toPixel(world);
  cairo_line_to(cr, p.x(), p.y());
}

void ringPath(cairo_t* cr, const CoveragePlotLayout& layout, const Ring& ring) {
  if (ring.empty()) return;
  moveTo(cr, layout, ring.front());
  for (std::size_t i = 1; i < ring.size(); ++i) lineTo(cr, layout, ring[i]);
  cairo_close_path(cr);
}

/// The path of an area, to be filled or clipped with the even-odd rule.
void areaPath(cairo_t* cr, const CoveragePlotLayout& layout, const PolygonWithHoles& area) {
  ringPath(cr, layout, area.hull);
  for (const Ring& hole : area.holes) ringPath(cr, layout, hole);
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
}

void posePath(cairo_t* cr, const CoveragePlotLayout& layout, const std::vector<Pose2>& poses) {
  moveTo(cr, layout, poses.front().position());
  for (std::size_t i = 1; i < poses.size(); ++i) lineTo(cr, layout, poses[i].position());
}

void setDash(cairo_t* cr, double on, double off) {
  const std::array<double, 2> dashes{on, off};
  cairo_set_dash(cr, dashes.data(), 2, 0.0);
}

/// The waypoint path's dash lengths, pixels at the base image size.
constexpr double kWaypointDashOn = 6.0;
constexpr double kWaypointDashOff = 4.0;

/// A dashed outline: its colour, width and dash lengths (pixels at the base image size).
struct DashedLine {
  PlotColour colour;
  double width = 1.0;
  double on = 1.0;
  double off = 1.0;
};

/// The offset free area's outline, and that of the parts not entered.
constexpr DashedLine kOffsetAreaLine{kOffsetAreaColour, kNominalOffsetOutlineWidth, 7.0, 4.0};
constexpr DashedLine kUnreachablePartLine{kUnseenRegionColour, 1.8, 4.0, 3.0};

/// Strokes the current path as `line`, its width scaled by `width_factor` but at least a
/// hairline, its dashes by `dash_factor`.
void strokeDashed(cairo_t* cr, const DashedLine& line, double width_factor, double dash_factor) {
  setColour(cr, line.colour);
  cairo_set_line_width(cr,
                       std::max(line.width * width_factor, CoveragePlotPathStyle::kHairlineWidth));
  setDash(cr, line.on * dash_factor, line.off * dash_factor);
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0.0);
}

std::uint32_t packedColour(const PlotColour& colour) {
  return 0xff000000u | (std::uint32_t{colour.red} << 16) | (std::uint32_t{colour.green} << 8) |
         std::uint32_t{colour.blue};
}

struct SurfaceDeleter {
  void operator()(cairo_surface_t* surface) const { cairo_surface_destroy(surface); }
};
using SurfacePtr = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;

/// The first of `count` grid lines that image line `line` of `lines` covers.
std::size_t firstCovered(int line, int lines, int count) {
  return static_cast<std::size_t>(line) * count / lines;
}

/// The heatmap as an image, top row = the grid's last row: one pixel per cell where cells
/// are at least a plot pixel (at most kMaxHeatmapImageSide a side), else one pixel per
/// block of the cells a plot pixel covers, showing the block's most common visit class
/// (ties to the fewer visits), so that overlap bands narrower than a pixel do not alias
/// into stripes on a lake's plot.
SurfacePtr heatmapImage(const Heatmap& heatmap, double pixels_per_cell) {
  const double shrink = std::min(1.0, pixels_per_cell);
  const auto side = [&](int cells) {
    return std::clamp(static_cast<int>(std::ceil(cells * shrink)), 1,
                      std::min(cells, kMaxHeatmapImageSide));
  };
  const int columns = side(heatmap.columns);
  const int rows = side(heatmap.rows);
  SurfacePtr image(cairo_image_surface_create(CAIRO_FORMAT_RGB24, columns, rows));
  if (cairo_surface_status(image.get()) != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error("coverage plot: cannot allocate the heatmap image");
  }
  std::array<std::uint32_t, kVisitColours.size()> palette;
  for (std::size_t i = 0; i < palette.size(); ++i) palette[i] = packedColour(kVisitColours[i]);
  const std::size_t last_class = palette.size() - 1;
  cairo_surface_flush(image.get());
  unsigned char* pixels = cairo_image_surface_get_data(image.get());
  const int stride = cairo_image_surface_get_stride(image.get());
  for (int r = 0; r < rows; ++r) {
    // Image row r covers grid rows [low, high), counted from the top.
    const std::size_t low = firstCovered(r, rows, heatmap.rows);
    const std::size_t high = std::max(low + 1, firstCovered(r + 1, rows, heatmap.rows));
    auto* line = reinterpret_cast<std::uint32_t*>(pixels + static_cast<std::size_t>(r) * stride);
    for (int c = 0; c < columns; ++c) {
      const std::size_t left = firstCovered(c, columns, heatmap.columns);
      const std::size_t right = std::max(left + 1, firstCovered(c + 1, columns, heatmap.columns));
      std::array<std::size_t, kVisitColours.size()> counts{};
      for (std::size_t from_top = low; from_top < high; ++from_top) {
        const std::uint16_t* visits =
            heatmap.visits.data() + (heatmap.rows - 1 - from_top) * heatmap.columns;
        for (std::size_t k = left; k < right; ++k) {
          ++counts[std::min<std::size_t>(visits[k], last_class)];
        }
      }
      line[c] = palette[std::max_element(counts.begin(), counts.end()) - counts.begin()];
    }
  }
  cairo_surface_mark_dirty(image.get());
  return image;
}

/// The free area: a light fill, the heatmap clipped to it, then the obstacles and outlines.
void drawAreas(cairo_t* cr, const CoveragePlotLayout& layout, const CoveragePlotData& data,
               const PlotScale& scale, const CoveragePlotPathStyle& style) {
  areaPath(cr, layout, data.free_area);
  setColour(cr, kFreeAreaColour);
  cairo_fill(cr);

  if (data.heatmap) {
    const Heatmap& heatmap = *data.heatmap;
    const double pixels_per_cell = layout.pixels_per_metre * heatmap.cell_size;
    const SurfacePtr image = heatmapImage(heatmap, pixels_per_cell);
    cairo_save(cr);
    areaPath(cr, layout, data.free_area);
    cairo_clip(cr);
    const Point2 top_left =
        layout.toPixel(heatmap.origin + Point2(0.0, heatmap.rows * heatmap.cell_size));
    cairo_translate(cr, top_left.x(), top_left.y());
    cairo_scale(cr, pixels_per_cell * heatmap.columns / cairo_image_surface_get_width(image.get()),
                pixels_per_cell * heatmap.rows / cairo_image_surface_get_height(image.get()));
    cairo_set_source_surface(cr, image.get(), 0.0, 0.0);
    cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);
    cairo_paint(cr);
    cairo_restore(cr);
  }

  for (const Ring& hole : data.free_area.holes) ringPath(cr, layout, hole);
  setColour(cr, kObstacleColour);
  cairo_fill_preserve(cr);
  setColour(cr, kOutlineColour);
  cairo_set_line_width(cr, 1.2 * scale.factor);
  cairo_stroke(cr);

  ringPath(cr, layout, data.free_area.hull);
  cairo_set_line_width(cr, 1.7 * scale.factor);
  cairo_stroke(cr);

  const double width_factor = style.offset_outline_width / kNominalOffsetOutlineWidth;
  const double dash_factor = style.mark_share * scale.factor;
  if (!data.offset_parts.empty()) {
    for (const PolygonWithHoles& part : data.offset_parts) areaPath(cr, layout, part);
    strokeDashed(cr, kOffsetAreaLine, width_factor, dash_factor);
  }
  if (!data.unreachable_parts.empty()) {
    for (const PolygonWithHoles& part : data.unreachable_parts) areaPath(cr, layout, part);
    strokeDashed(cr, kUnreachablePartLine, width_factor, dash_factor);
  }
}

/// The waypoint path dashed, with a dot at each waypoint unless the lanes are too close.
void drawWaypointPath(cairo_t* cr, const CoveragePlotLayout& layout,
                      const std::vector<Pose2>& waypoints, const PlotScale& scale,
                      const CoveragePlotPathStyle& style) {
  if (waypoints.empty()) return;
  setColour(cr, kWaypointColour, style.path_opacity);
  if (waypoints.size() > 1) {
    posePath(cr, layout, waypoints);
    cairo_set_line_width(cr, style.waypoint_width);
    const double dash_factor = style.mark_share * scale.factor;
    setDash(cr, kWaypointDashOn * dash_factor, kWaypointDashOff * dash_factor);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0.0);
  }
  if (style.waypoint_dot_radius <= 0.0) return;
  for (const Pose2& pose : waypoints) {
    const Point2 p = layout.toPixel(pose.position());
    cairo_new_sub_path(cr);
    cairo_arc(cr, p.x(), p.y(), style.waypoint_dot_radius, 0.0, 2.0 * M_PI);
  }
  cairo_fill(cr);
}

/// A filled arrowhead `length` pixels long centred on pixel `centre`, pointing along world
/// heading `yaw`.
void arrowPath(cairo_t* cr, const Point2& centre, double yaw, double length) {
  const Point2 along(std::cos(yaw), -std::sin(yaw));
  const Point2 across(-along.y(), along.x());
  const double half_width = kArrowHalfWidthShare * length;
  const Point2 tip = centre + 0.5 * length * along;
  const Point2 back = centre - 0.5 * length * along;
  cairo_move_to(cr, tip.x(), tip.y());
  cairo_line_to(cr, back.x() + half_width * across.x(), back.y() + half_width * across.y());
  cairo_line_to(cr, back.x() + 0.3 * length * along.x(), back.y() + 0.3 * length * along.y());
  cairo_line_to(cr, back.x() - half_width * across.x(), back.y() - half_width * across.y());
  cairo_close_path(cr);
}

double wrappedAngle(double angle) { return std::remainder(angle, 2.0 * M_PI); }

/// The trajectory with heading arrows, or red without them under actual pose arrows.
void drawTrajectory(cairo_t* cr, const CoveragePlotLayout& layout, const CoveragePlotData& data,
                    const CoveragePlotPathStyle& style) {
  const std::vector<Pose2>& trajectory = data.trajectory;
  if (trajectory.size() < 2) return;
  const bool under_arrows = !data.actual_pose_arrows.empty();
  setColour(cr, under_arrows ? kDesiredColour : kTrajectoryColour, style.path_opacity);
  posePath(cr, layout, trajectory);
  cairo_set_line_width(cr, style.trajectory_width);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_stroke(cr);
  if (under_arrows) return;

  setColour(cr, kTrajectoryColour);
  const double spacing = style.arrow_spacing_pixels / layout.pixels_per_metre;
  double travelled = 0.0;
  double next_arrow = 0.5 * spacing;
  for (std::size_t i = 1; i < trajectory.size(); ++i) {
    const Pose2& from = trajectory[i - 1];
    const Pose2& to = trajectory[i];
    const double length = (to.position() - from.position()).norm();
    while (travelled + length >= next_arrow) {
      const double t = (next_arrow - travelled) / length;
      const Point2 position = from.position() + t * (to.position() - from.position());
      const double yaw = from.yaw + t * wrappedAngle(to.yaw - from.yaw);
      arrowPath(cr, layout.toPixel(position), yaw, style.arrow_length);
      next_arrow += spacing;
    }
    travelled += length;
  }
  cairo_fill(cr);
}

/// The actual poses as black arrows, smaller than the trajectory's heading arrows.
void drawPoseArrows(cairo_t* cr, const CoveragePlotLayout& layout, const CoveragePlotData& data,
                    const PlotScale& scale) {
  if (data.actual_pose_arrows.empty()) return;
  setColour(cr, kTrajectoryColour);
  for (const Pose2& pose : data.actual_pose_arrows) {
    arrowPath(cr, layout.toPixel(pose.position()), pose.yaw,
              kPoseArrowShare * kNominalArrowLength * scale.factor);
  }
  cairo_fill(cr);
}

/// The least top of the tracking error's colour scale, metres: millimetre deviations of a
/// well-tracked path stay dark instead of spanning the whole colour map.
constexpr double kMinErrorScale = 0.05;

/// The top of the tracking error's colour scale: the largest error of the actual path,
/// at least kMinErrorScale.
double errorScale(const std::vector<double>& errors) {
  double largest = 0.0;
  for (const double error : errors) largest = std::max(largest, error);
  return std::max(largest, kMinErrorScale);
}

/// The actual path, each piece coloured by its ends' mean tracking error.
void drawActualPath(cairo_t* cr, const CoveragePlotLayout& layout, const CoveragePlotData& data,
                    const PlotScale& scale) {
  if (data.actual_path.size() < 2) return;
  const double top = errorScale(data.actual_errors);
  cairo_set_line_width(cr, 2.4 * scale.factor);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (std::size_t i = 1; i < data.actual_path.size(); ++i) {
    const double error = 0.5 * (data.actual_errors[i - 1] + data.actual_errors[i]);
    setColour(cr, CoveragePlot::errorColour(error / top));
    moveTo(cr, layout, data.actual_path[i - 1].position());
    lineTo(cr, layout, data.actual_path[i].position());
    cairo_stroke(cr);
  }
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
}

/// Text with a white halo, readable over the heatmap and lines.
void showHaloText(cairo_t* cr, const std::string& text, double x, double y, TextAlign horizontal,
                  const PlotScale& scale) {
  moveToText(cr, text, x, y, horizontal);
  cairo_text_path(cr, text.c_str());
  cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
  cairo_set_line_width(cr, 3.5 * scale.factor);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_stroke_preserve(cr);
  setColour(cr, kTextColour);
  cairo_fill(cr);
}

void startMarkerPath(cairo_t* cr, const Point2& centre, const PlotScale& scale) {
  cairo_new_sub_path(cr);
  cairo_arc(cr, centre.x(), centre.y(), 7.0 * scale.factor, 0.0, 2.0 * M_PI);
}

void goalMarkerPath(cairo_t* cr, const Point2& centre, const PlotScale& scale) {
  const double half = 6.5 * scale.factor;
  cairo_rectangle(cr, centre.x() - half, centre.y() - half, 2.0 * half, 2.0 * half);
}

void fillMarker(cairo_t* cr, const PlotColour& colour, const PlotScale& scale) {
  setColour(cr, colour);
  cairo_fill_preserve(cr);
  cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
  cairo_set_line_width(cr, 1.5 * scale.factor);
  cairo_stroke(cr);
}

/// Start (green disc, labelled above) and goal (purple square, labelled below).
/// The largest unseen region's outline (its bounding box, a few pixels outside it so that
/// the walls it lies along do not hide it), circled too where it is only a few pixels
/// across.
void drawUnseenRegion(cairo_t* cr, const CoveragePlotLayout& layout, const CoveragePlotData& data,
                      const PlotScale& scale) {
  if (!data.unseen_region || data.unseen_region->empty()) return;
  Point2 low = layout.toPixel(data.unseen_region->front());
  Point2 high = low;
  for (const Point2& p : *data.unseen_region) {
    low = low.cwiseMin(layout.toPixel(p));
    high = high.cwiseMax(layout.toPixel(p));
  }
  const double margin = kUnseenRegionMarginPixels * scale.factor;
  setColour(cr, kUnseenRegionColour);
  cairo_set_line_width(cr, 2.2 * scale.factor);
  cairo_rectangle(cr, low.x() - margin, low.y() - margin, high.x() - low.x() + 2.0 * margin,
                  high.y() - low.y() + 2.0 * margin);
  cairo_stroke(cr);
  if ((high - low).norm() < kUnseenRegionMinPixels * scale.factor) {
    const Point2 centre = 0.5 * (low + high);
    cairo_new_sub_path(cr);
    cairo_arc(cr, centre.x(), centre.y(), kUnseenRegionMinPixels * scale.factor, 0.0, 2.0 * M_PI);
    cairo_stroke(cr);
  }
}

/// A circle with a cross of radius `radius` pixels around `centre`: the closest approach.
void closestApproachPath(cairo_t* cr, const Point2& centre, double radius) {
  cairo_new_sub_path(cr);
  cairo_arc(cr, centre.x(), centre.y(), radius, 0.0, 2.0 * M_PI);
  const double arm = kClosestApproachCrossShare * radius;
  cairo_move_to(cr, centre.x() - arm, centre.y() - arm);
  cairo_line_to(cr, centre.x() + arm, centre.y() + arm);
  cairo_move_to(cr, centre.x() - arm, centre.y() + arm);
  cairo_line_to(cr, centre.x() + arm, centre.y() - arm);
}

/// Where the trajectory comes nearer the walls than wall_distance.
void drawClosestApproach(cairo_t* cr, const CoveragePlotLayout& layout,
                         const CoveragePlotData& data, const PlotScale& scale) {
  if (!data.closest_approach) return;
  closestApproachPath(cr, layout.toPixel(*data.closest_approach),
                      kUnseenRegionMinPixels * scale.factor);
  setColour(cr, kUnseenRegionColour);
  cairo_set_line_width(cr, 2.2 * scale.factor);
  cairo_stroke(cr);
}

void drawMarkers(cairo_t* cr, const CoveragePlotLayout& layout, const CoveragePlotData& data,
                 const PlotScale& scale) {
  selectFont(cr, scale.legend, true);
  if (data.start) {
    const Point2 p = layout.toPixel(*data.start);
    startMarkerPath(cr, p, scale);
    fillMarker(cr, kStartColour, scale);
    showHaloText(cr, "start", p.x() + 10.0 * scale.factor, p.y() - 13.0 * scale.factor,
                 TextAlign::kStart, scale);
  }
  if (data.goal) {
    const Point2 p = layout.toPixel(*data.goal);
    goalMarkerPath(cr, p, scale);
    fillMarker(cr, kGoalColour, scale);
    showHaloText(cr, "goal", p.x() + 10.0 * scale.factor, p.y() + 14.0 * scale.factor,
                 TextAlign::kStart, scale);
  }
}

void drawAxes(cairo_t* cr, const CoveragePlotLayout& layout, const PlotScale& scale) {
  const double left = layout.box_left;
  const double top = layout.box_top;
  const double right = left + layout.box_width;
  const double bottom = top + layout.box_height;
  const double tick_length = 6.0 * scale.factor;
  const double line_width = 1.2 * scale.factor;
  setColour(cr, kOutlineColour);
  cairo_set_line_width(cr, line_width);
  cairo_rectangle(cr, left, top, layout.box_width, layout.box_height);
  cairo_stroke(cr);

  const Point2 world_max =
      layout.box_world_min + Point2(layout.box_width, layout.box_height) / layout.pixels_per_metre;
  const double step = niceStep(
      std::max(world_max.x() - layout.box_world_min.x(), world_max.y() - layout.box_world_min.y()),
      std::max(layout.box_width, layout.box_height) / (kTickSpacingPixels * scale.factor));
  selectFont(cr, scale.tick, false);
  for (const double x : ticks(layout.box_world_min.x(), world_max.x(), step)) {
    const double px = layout.toPixel(Point2(x, 0.0)).x();
    cairo_move_to(cr, px, bottom);
    cairo_line_to(cr, px, bottom + tick_length);
    showText(cr, tickLabel(x, step), px, bottom + tick_length + 0.85 * scale.tick,
             TextAlign::kCentre);
  }
  for (const double y : ticks(layout.box_world_min.y(), world_max.y(), step)) {
    const double py = layout.toPixel(Point2(0.0, y)).y();
    cairo_move_to(cr, left, py);
    cairo_line_to(cr, left - tick_length, py);
    showText(cr, tickLabel(y, step), left - tick_length - 4.0 * scale.factor, py, TextAlign::kEnd);
  }
  cairo_stroke(cr);

  selectFont(cr, scale.label, false);
  showText(cr, "x [m]", 0.5 * (left + right), bottom + tick_length + 2.4 * scale.label,
           TextAlign::kCentre);
  cairo_save(cr);
  cairo_translate(cr, left - tick_length - 4.4 * scale.label, 0.5 * (top + bottom));
  cairo_rotate(cr, -0.5 * M_PI);
  showText(cr, "y [m]", 0.0, 0.0, TextAlign::kCentre);
  cairo_restore(cr);
}

void drawTitle(cairo_t* cr, const CoveragePlotLayout& layout, const std::vector<std::string>& lines,
               const PlotScale& scale) {
  const double centre = layout.box_left + 0.5 * layout.box_width;
  double y = 18.0 * scale.factor + 0.6 * scale.title;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const bool title = i == 0;
    selectFont(cr, title ? scale.title : scale.subtitle, title);
    setColour(cr, title ? kTextColour : kSubtitleColour);
    showText(cr, lines[i], centre, y, TextAlign::kCentre);
    y += 1.35 * (title ? 0.5 * (scale.title + scale.subtitle) : scale.subtitle);
  }
}

/// The tracking error's colour bar, from 0 at the bottom to the largest error at the top,
/// with its title at `y` in the legend column at `x`.
void drawErrorBar(cairo_t* cr, const CoveragePlotData& data, double x, double y,
                  const PlotScale& scale) {
  const double f = scale.factor;
  selectFont(cr, scale.legend, true);
  setColour(cr, kTextColour);
  showText(cr, "tracking error [m]", x, y, TextAlign::kStart);
  y += 0.8 * 25.0 * f;
  const double bar_width = 22.0 * f;
  const double bar_height = 120.0 * f;
  const double top = errorScale(data.actual_errors);
  cairo_pattern_t* gradient = cairo_pattern_create_linear(0.0, y + bar_height, 0.0, y);
  for (std::size_t i = 0; i < kErrorColours.size(); ++i) {
    const PlotColour& colour = kErrorColours[i];
    cairo_pattern_add_color_stop_rgb(gradient, static_cast<double>(i) / (kErrorColours.size() - 1),
                                     colour.red / 255.0, colour.green / 255.0, colour.blue / 255.0);
  }
  cairo_rectangle(cr, x, y, bar_width, bar_height);
  cairo_set_source(cr, gradient);
  cairo_fill(cr);
  cairo_pattern_destroy(gradient);
  setColour(cr, kOutlineColour);
  cairo_set_line_width(cr, 1.0 * f);
  cairo_rectangle(cr, x, y, bar_width, bar_height);
  cairo_stroke(cr);
  selectFont(cr, scale.legend, false);
  setColour(cr, kTextColour);
  for (const double share : {0.0, 0.5, 1.0}) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.2g", share * top);
    showText(cr, text, x + bar_width + 8.0 * f, y + (1.0 - share) * bar_height, TextAlign::kStart);
  }
}

/// A column of legend rows right of the box: each row's sample at x, its label beside it.
struct LegendColumn {
  cairo_t* cr;
  const PlotScale& scale;
  double x;
  double sample_width;
  double label_x;
  double row_height;
  double y;  ///< the middle of the next row

  /// Writes the current row's label and moves to the next row.
  void label(const std::string& text) {
    selectFont(cr, scale.legend, false);
    setColour(cr, kTextColour);
    showText(cr, text, label_x, y, TextAlign::kStart);
    y += row_height;
  }
};

/// The keys to the lines: trajectory, actual path, waypoint path, offset free area.
void drawLineKeys(LegendColumn& column, const CoveragePlotData& data) {
  cairo_t* cr = column.cr;
  const double f = column.scale.factor;
  const double x = column.x;
  const double sample_width = column.sample_width;
  const bool under_arrows = !data.actual_pose_arrows.empty();
  if (data.trajectory.size() > 1) {
    setColour(cr, under_arrows ? kDesiredColour : kTrajectoryColour);
    cairo_move_to(cr, x, column.y);
    cairo_line_to(cr, x + sample_width, column.y);
    cairo_set_line_width(cr, kNominalTrajectoryWidth * f);
    cairo_stroke(cr);
    if (!under_arrows) {
      arrowPath(cr, Point2(x + 0.5 * sample_width, column.y), 0.0, kNominalArrowLength * f);
      cairo_fill(cr);
    }
    column.label(under_arrows ? "desired trajectory" : "trajectory");
  }
  if (under_arrows) {
    setColour(cr, kTrajectoryColour);
    arrowPath(cr, Point2(x + 0.5 * sample_width, column.y), 0.0, kNominalArrowLength * f);
    cairo_fill(cr);
    column.label("actual poses");
  }
  if (data.actual_path.size() > 1) {
    cairo_set_line_width(cr, 2.4 * f);
    for (int piece = 0; piece < 4; ++piece) {
      setColour(cr, CoveragePlot::errorColour(piece / 3.0));
      cairo_move_to(cr, x + piece * sample_width / 4.0, column.y);
      cairo_line_to(cr, x + (piece + 1) * sample_width / 4.0, column.y);
      cairo_stroke(cr);
    }
    column.label("actual path");
  }
  if (!data.waypoints.empty()) {
    setColour(cr, kWaypointColour);
    cairo_move_to(cr, x, column.y);
    cairo_line_to(cr, x + sample_width, column.y);
    cairo_set_line_width(cr, kNominalWaypointWidth * f);
    setDash(cr, kWaypointDashOn * f, kWaypointDashOff * f);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0.0);
    for (const double dot_x : {x + 2.0 * f, x + sample_width - 2.0 * f}) {
      cairo_new_sub_path(cr);
      cairo_arc(cr, dot_x, column.y, kNominalWaypointDotRadius * f, 0.0, 2.0 * M_PI);
    }
    cairo_fill(cr);
    column.label("waypoint path");
  }
  for (const auto& [shown, line, label] :
       {std::tuple{!data.offset_parts.empty(), kOffsetAreaLine, "offset free area"},
        std::tuple{!data.unreachable_parts.empty(), kUnreachablePartLine, "beyond narrow gap"}}) {
    if (!shown) continue;
    cairo_move_to(cr, x, column.y);
    cairo_line_to(cr, x + sample_width, column.y);
    strokeDashed(cr, line, f, f);
    column.label(label);
  }
}

/// The keys to the outlined and filled shapes: the largest unseen region, obstacles, the
/// start and the goal.
void drawShapeKeys(LegendColumn& column, const CoveragePlotData& data) {
  cairo_t* cr = column.cr;
  const double f = column.scale.factor;
  const double x = column.x;
  const double sample_width = column.sample_width;
  if (data.unseen_region) {
    cairo_rectangle(cr, x + 0.5 * (sample_width - 16.0 * f), column.y - 8.0 * f, 16.0 * f,
                    16.0 * f);
    setColour(cr, kUnseenRegionColour);
    cairo_set_line_width(cr, 2.2 * f);
    cairo_stroke(cr);
    column.label("largest unseen region");
  }
  if (data.closest_approach) {
    closestApproachPath(cr, Point2(x + 0.5 * sample_width, column.y), 8.0 * f);
    setColour(cr, kUnseenRegionColour);
    cairo_set_line_width(cr, 2.2 * f);
    cairo_stroke(cr);
    column.label("in the wall band");
  }
  if (!data.free_area.holes.empty()) {
    cairo_rectangle(cr, x + 0.5 * (sample_width - 16.0 * f), column.y - 8.0 * f, 16.0 * f,
                    16.0 * f);
    setColour(cr, kObstacleColour);
    cairo_fill_preserve(cr);
    setColour(cr, kOutlineColour);
    cairo_set_line_width(cr, 1.2 * f);
    cairo_stroke(cr);
    column.label("obstacle");
  }
  if (data.start) {
    startMarkerPath(cr, Point2(x + 0.5 * sample_width, column.y), column.scale);
    fillMarker(cr, kStartColour, column.scale);
    column.label("start");
  }
  if (data.goal) {
    goalMarkerPath(cr, Point2(x + 0.5 * sample_width, column.y), column.scale);
    fillMarker(cr, kGoalColour, column.scale);
    column.label("goal");
  }
}

/// The colour bar of the heatmap's visit counts, under a "visits" heading.
void drawVisitKey(LegendColumn& column) {
  cairo_t* cr = column.cr;
  const double f = column.scale.factor;
  const double x = column.x;
  column.y += 0.6 * column.row_height;
  selectFont(cr, column.scale.legend, true);
  setColour(cr, kTextColour);
  showText(cr, "visits", x, column.y, TextAlign::kStart);
  column.y += 0.8 * column.row_height;
  const double swatch_width = 22.0 * f;
  const double swatch_height = 24.0 * f;
  const std::array<const char*, kVisitColours.size()> names{"0  unseen", "1  seen once", "2", "3",
                                                            "4+"};
  const double bar_top = column.y;
  selectFont(cr, column.scale.legend, false);
  for (std::size_t i = kVisitColours.size(); i-- > 0;) {
    cairo_rectangle(cr, x, column.y, swatch_width, swatch_height);
    setColour(cr, kVisitColours[i]);
    cairo_fill(cr);
    setColour(cr, kTextColour);
    showText(cr, names[i], x + swatch_width + 8.0 * f, column.y + 0.5 * swatch_height,
             TextAlign::kStart);
    column.y += swatch_height;
  }
  setColour(cr, kOutlineColour);
  cairo_set_line_width(cr, 1.0 * f);
  cairo_rectangle(cr, x, bar_top, swatch_width, column.y - bar_top);
  cairo_stroke(cr);
  column.y += 0.6 * column.row_height;
}

/// The key to the lines and markers, then the colour bars of the heatmap and of the
/// tracking error, right of the box.
void drawLegend(cairo_t* cr, const CoveragePlotLayout& layout, const CoveragePlotData& data,
                const PlotScale& scale) {
  const double f = scale.factor;
  const double x = layout.box_left + layout.box_width + 24.0 * f;
  const double sample_width = 34.0 * f;
  const double row_height = 25.0 * f;
  LegendColumn column{cr,
                      scale,
                      x,
                      sample_width,
                      x + sample_width + 10.0 * f,
                      row_height,
                      layout.box_top + 0.5 * row_height};
  drawLineKeys(column, data);
  drawShapeKeys(column, data);
  if (data.heatmap) drawVisitKey(column);
  if (data.actual_path.size() > 1) {
    drawErrorBar(cr, data, x, column.y + 0.6 * row_height, scale);
  }
}

}  // namespace

Point2 CoveragePlotLayout::toPixel(const Point2& world) const {
  return {box_left + (world.x() - box_world_min.x()) * pixels_per_metre,
          box_top + box_height - (world.y() - box_world_min.y()) * pixels_per_metre};
}

CoveragePlot::CoveragePlot(const CoveragePlotOptions& options) : options_(options) {
  const auto in_range = [](int side) {
    return side >= CoveragePlotOptions::kMinSide && side <= CoveragePlotOptions::kMaxSide;
  };
  if (!in_range(options.width) || (options.height != 0 && !in_range(options.height))) {
    throw InvalidInputError("coverage plot: size " + std::to_string(options.width) + " x " +
                            std::to_string(options.height) + " pixels, each side must be in [" +
                            std::to_string(CoveragePlotOptions::kMinSide) + ", " +
                            std::to_string(CoveragePlotOptions::kMaxSide) + "] (height 0: auto)");
  }
  if (!std::isfinite(options.arrow_spacing) || options.arrow_spacing < 0.0) {
    throw InvalidInputError("coverage plot: arrow spacing must be finite and >= 0, got " +
                            std::to_string(options.arrow_spacing));
  }
}

CoveragePlotLayout CoveragePlot::layout(const CoveragePlotData& data) const {
  return computeLayout(data, options_);
}

CoveragePlotPathStyle CoveragePlot::pathStyle(const CoveragePlotData& data) const {
  const CoveragePlotLayout layout = computeLayout(data, options_);
  return pathStyleFor(layout, data, options_.arrow_spacing, plotScaleFor(layout.width));
}

void CoveragePlot::writePng(const CoveragePlotData& data, const std::string& path) const {
  const CoveragePlotLayout layout = computeLayout(data, options_);
  const PlotScale scale = plotScaleFor(layout.width);
  const CoveragePlotPathStyle style = pathStyleFor(layout, data, options_.arrow_spacing, scale);
  const PlotCanvas canvas(layout.width, layout.height, "coverage plot");
  cairo_t* cr = canvas.context();

  cairo_save(cr);
  cairo_rectangle(cr, layout.box_left, layout.box_top, layout.box_width, layout.box_height);
  cairo_clip(cr);
  drawAreas(cr, layout, data, scale, style);
  drawWaypointPath(cr, layout, data.waypoints, scale, style);
  drawTrajectory(cr, layout, data, style);
  drawActualPath(cr, layout, data, scale);
  drawPoseArrows(cr, layout, data, scale);
  drawUnseenRegion(cr, layout, data, scale);
  drawClosestApproach(cr, layout, data, scale);
  drawMarkers(cr, layout, data, scale);
  drawMapOverlays(cr, layout, data, scale);
  cairo_restore(cr);

  drawAxes(cr, layout, scale);
  drawTitle(cr, layout, data.title_lines, scale);
  drawLegend(cr, layout, data, scale);

  canvas.writePng(path, "coverage plot");
}

PlotColour CoveragePlot::visitColour(std::uint16_t visits) {
  return kVisitColours[std::min<std::size_t>(visits, kVisitColours.size() - 1)];
}

PlotColour CoveragePlot::errorColour(double fraction) {
  const double position =
      std::clamp(std::isfinite(fraction) ? fraction : 0.0, 0.0, 1.0) * (kErrorColours.size() - 1);
  const std::size_t below = std::min(static_cast<std::size_t>(position), kErrorColours.size() - 2);
  const double t = position - static_cast<double>(below);
  const auto mix = [&](std::uint8_t a, std::uint8_t b) {
    return static_cast<std::uint8_t>(std::lround(a + t * (b - a)));
  };
  const PlotColour& low = kErrorColours[below];
  const PlotColour& high = kErrorColours[below + 1];
  return {mix(low.red, high.red), mix(low.green, high.green), mix(low.blue, high.blue)};
}

}  // namespace kinematic_coverage::core
