#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "polygon_coverage_ros_bridge/sweeps/seen_area.h"

namespace kinematic_coverage::core {

/// What a coverage plot shows: the map, the plan and what the sensor saw, as in the
/// thesis's trajectory and heatmap figures (Fig. 4.2, Fig. 4.6).
struct CoveragePlotData {
  /// The raw free area: the hull outlined, the holes filled as obstacles. The hull needs
  /// at least 3 vertices and a non-zero extent in x and y.
  PolygonWithHoles free_area;
  /// The parts of the offset free area (free area shrunk by wall_distance), outlined
  /// dashed; none drawn when empty.
  std::vector<PolygonWithHoles> offset_parts;
  /// Parts of the offset free area that are not entered (beyond a gap narrower than
  /// gap_clearance: they count as unreachable), outlined dashed in the unseen region's
  /// colour; none drawn when empty.
  std::vector<PolygonWithHoles> unreachable_parts;
  /// Visit counts (the heatmap), drawn over the free area only.
  std::optional<Heatmap> heatmap;
  /// The planner's waypoint path, a thin dashed polyline with a dot at each waypoint.
  std::vector<Pose2> waypoints;
  /// The trajectory as sampled poses, a solid polyline with heading arrows; sample it
  /// densely (TrajectorySampler) so that arcs look round.
  std::vector<Pose2> trajectory;
  std::optional<Point2> start;
  std::optional<Point2> goal;
  /// The path a robot actually drove (coverage_tool simulate), drawn over the trajectory
  /// as a polyline coloured by `actual_errors` (from 0 to the largest error, at least
  /// 5 cm), with a colour bar of the error.
  std::vector<Pose2> actual_path;
  /// The tracking error at each pose of `actual_path`, metres, >= 0: one per pose.
  std::vector<double> actual_errors;
  /// Poses the robot drove, drawn as black arrows (the thesis's Fig. 4.3); when there are
  /// any, the trajectory is drawn red, without its own heading arrows.
  std::vector<Pose2> actual_pose_arrows;
  /// The largest piece of the reachable area left unseen (its bounding box), outlined in
  /// red; none drawn when unset.
  std::optional<Ring> unseen_region;
  /// Where the trajectory comes nearer the walls than wall_distance (a gap narrower than two
  /// wall distances, or turns the user let into the wall band), circled with a cross in the
  /// unseen region's colour; none drawn when unset.
  std::optional<Point2> closest_approach;
  /// Lines above the plot: the first is the title (bold), the others key metrics.
  std::vector<std::string> title_lines;
  /// The direction of true north in the plot's frame, radians counter-clockwise from +x
  /// (pi/2 in a local east-north frame, a little off it on a UTM grid): a north arrow
  /// points there. Unset for a mission with no geo-reference: no north arrow.
  std::optional<double> north_direction;
};

/// Image size and drawing choices of a coverage plot.
struct CoveragePlotOptions {
  /// Image width, pixels, in [kMinSide, kMaxSide]; fonts, margins and line widths grow
  /// with its square root.
  int width = 1200;
  /// Image height, pixels, in [kMinSide, kMaxSide]; 0 chooses it from the area's aspect.
  int height = 0;
  /// Arc length between heading arrows on the trajectory, metres; 0 puts one about every
  /// 100 pixels of trajectory. Either way, arrows are thinned out where they would cover
  /// more than a few percent of the free area (dense lanes of a large map).
  double arrow_spacing = 0.0;

  static constexpr int kMinSide = 300;
  static constexpr int kMaxSide = 16384;
};

/// An opaque sRGB colour, 8 bits per channel.
struct PlotColour {
  std::uint8_t red = 0;
  std::uint8_t green = 0;
  std::uint8_t blue = 0;
};

/// The fill of obstacles (holes of the free area).
inline constexpr PlotColour kObstacleColour{158, 158, 158};
/// The fill of the free area where no heatmap cell lies.
inline constexpr PlotColour kFreeAreaColour{246, 246, 246};
/// The image background, also outside the hull.
inline constexpr PlotColour kBackgroundColour{255, 255, 255};

/// Where a plot puts the world: the image size and the equal-aspect map from metres to
/// pixels (x to the right, y downwards, pixel (i, j) covering [i, i+1) x [j, j+1)).
struct CoveragePlotLayout {
  int width = 0;
  int height = 0;
  /// The axes box, pixels.
  double box_left = 0.0;
  double box_top = 0.0;
  double box_width = 0.0;
  double box_height = 0.0;
  /// Scale, the same along x and y.
  double pixels_per_metre = 1.0;
  /// The world point at the box's bottom-left corner.
  Point2 box_world_min = Point2::Zero();

  /// Image coordinates of a world point.
  Point2 toPixel(const Point2& world) const;
};

/// How the paths are drawn at a plot's scale: where the trajectory's lanes come close on
/// the image (a lake of square kilometres), lines get thinner down to a hairline, fainter
/// below it, and arrowheads, dashes and waypoint dots shrink, so that the heatmap stays
/// visible between the lanes; where they are far apart (a 30 m map), the nominal sizes.
struct CoveragePlotPathStyle {
  /// Typical on-image distance between neighbouring lanes, pixels: the free area divided
  /// by the length of the trajectory (of the waypoint path without one), both on the
  /// image; infinite without either.
  double lane_spacing_pixels = 0.0;
  /// Trajectory line width, pixels: the nominal width, capped at an eighth of the lane
  /// spacing but at least a hairline (kHairlineWidth).
  double trajectory_width = 0.0;
  /// Waypoint path line width, pixels, scaled down as the trajectory's.
  double waypoint_width = 0.0;
  /// Offset free area outline width, pixels, scaled down as the trajectory's.
  double offset_outline_width = 0.0;
  /// Opacity of the trajectory and waypoint path, in (0, 1]: below 1 where the lanes
  /// are less than about 9 pixels apart, so that they tint the heatmap instead of hiding it.
  double path_opacity = 1.0;
  /// Share of their nominal size that arrowheads and dash lengths keep, in (0, 1].
  double mark_share = 1.0;
  /// Heading arrowhead length, pixels.
  double arrow_length = 0.0;
  /// On-image arc length between heading arrows, pixels.
  double arrow_spacing_pixels = 0.0;
  /// Waypoint dot radius, pixels; 0 when the dots are left out (lanes too close).
  double waypoint_dot_radius = 0.0;

  /// The thinnest line drawn, pixels.
  static constexpr double kHairlineWidth = 0.5;
};

/// Renders coverage plots to PNG files with cairo (`plot.png` of coverage_tool plan,
/// evaluate and simulate): obstacles, the heatmap in discrete colours
/// for 0, 1, 2, 3 and 4+ visits with its colour bar, paths, start and goal, an actual path
/// coloured by tracking error with its colour bar, title lines and axes in metres with an
/// equal aspect ratio, a scale bar and, for geo-referenced data, a north arrow.
class CoveragePlot {
 public:
  /// Throws InvalidInputError for a size out of range or a negative or non-finite arrow
  /// spacing.
  explicit CoveragePlot(const CoveragePlotOptions& options = {});

  /// Size and world-to-pixel map of the plot of `data`. Throws InvalidInputError as
  /// writePng does for bad data.
  CoveragePlotLayout layout(const CoveragePlotData& data) const;

  /// Line widths and marker sizes of the paths of the plot of `data` at its scale. Throws
  /// InvalidInputError as writePng does for bad data.
  CoveragePlotPathStyle pathStyle(const CoveragePlotData& data) const;

  /// Renders `data` and writes it to `path` as PNG. Throws InvalidInputError for a hull
  /// with fewer than 3 vertices or no extent, a non-finite coordinate, a heatmap whose
  /// grid is empty, non-finite or not columns x rows in size, actual errors that are not
  /// one finite value >= 0 per actual pose, a non-finite north direction, and naming `path` when
  /// the file cannot be written.
  void writePng(const CoveragePlotData& data, const std::string& path) const;

  /// Length of the scale bar of a box `box_width_metres` wide, metres: 1, 2 or 5 times a
  /// power of ten nearest (by ratio) to a fifth of the width, so between about 1/8 and 1/3
  /// of it: a round length, easy to read and to compare the lanes with.
  static double scaleBarLength(double box_width_metres);

  /// The scale bar's label: "500 m", "2 km", "0.5 m" (kilometres from 1 km on).
  static std::string scaleBarLabel(double length_metres);

  /// The heatmap colour of a cell seen `visits` times: red for unseen, then light to dark
  /// for 1, 2, 3 and 4 or more.
  static PlotColour visitColour(std::uint16_t visits);

  /// The colour of the actual path where its tracking error is `fraction` of the largest
  /// error (clamped to [0, 1]): dark purple for no error through magenta and orange to
  /// yellow for the largest (the "plasma" colour map).
  static PlotColour errorColour(double fraction);

 private:
  CoveragePlotOptions options_;
};

}  // namespace kinematic_coverage::core
