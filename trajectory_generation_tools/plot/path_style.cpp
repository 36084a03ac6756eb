#include "trajectory_generation_tools/plot/path_style.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// A line is at most this share of the lane spacing wide, so that the heatmap shows
/// between neighbouring lanes.
constexpr double kLaneWidthShare = 1.0 / 8.0;
/// Lanes at least this many pixels apart are drawn opaque; closer ones fainter in
/// proportion (they form a texture over the heatmap rather than lines one follows), down
/// to kMinPathOpacity.
constexpr double kOpaqueLaneSpacingPixels = 10.0;
constexpr double kMinPathOpacity = 0.35;
/// Least share of their nominal size that arrowheads and dashes keep, so that they stay
/// recognisable (arrowheads about 5 pixels long).
constexpr double kMinMarkShare = 0.45;
/// Waypoint dots are at most this share of the lane spacing in radius, and left out
/// below kMinWaypointDotRadius pixels.
constexpr double kWaypointDotLaneShare = 1.0 / 8.0;
constexpr double kMinWaypointDotRadius = 0.8;
/// Heading arrows cover at most this share of the free area on the image.
constexpr double kMaxArrowAreaShare = 0.015;
/// Least on-image distance between heading arrows, pixels.
constexpr double kMinArrowSpacingPixels = 12.0;

double pathLength(const std::vector<Pose2>& poses) {
  double length = 0.0;
  for (std::size_t i = 1; i < poses.size(); ++i) {
    length += (poses[i].position() - poses[i - 1].position()).norm();
  }
  return length;
}

}  // namespace

CoveragePlotPathStyle pathStyleFor(const CoveragePlotLayout& layout, const CoveragePlotData& data,
                                   double arrow_spacing, const PlotScale& scale) {
  const double f = scale.factor;
  const double ppm = layout.pixels_per_metre;
  const double free_pixels = area(data.free_area) * ppm * ppm;
  const double path_pixels =
      ppm * (data.trajectory.size() > 1 ? pathLength(data.trajectory) : pathLength(data.waypoints));

  CoveragePlotPathStyle style;
  style.lane_spacing_pixels = path_pixels > 0.0 && free_pixels > 0.0
                                  ? free_pixels / path_pixels
                                  : std::numeric_limits<double>::infinity();
  const double width_cap = kLaneWidthShare * style.lane_spacing_pixels;
  const double nominal_width = kNominalTrajectoryWidth * f;
  style.trajectory_width =
      std::max(std::min(nominal_width, width_cap), CoveragePlotPathStyle::kHairlineWidth);
  style.path_opacity =
      std::clamp(style.lane_spacing_pixels / kOpaqueLaneSpacingPixels, kMinPathOpacity, 1.0);
  const double share = std::min(width_cap / nominal_width, 1.0);
  const auto scaled = [&](double nominal) {
    return std::max(nominal * f * share, CoveragePlotPathStyle::kHairlineWidth);
  };
  style.waypoint_width = scaled(kNominalWaypointWidth);
  style.offset_outline_width = scaled(kNominalOffsetOutlineWidth);
  style.mark_share = std::max(share, kMinMarkShare);
  style.arrow_length = kNominalArrowLength * f * style.mark_share;

  const double radius =
      std::min(kNominalWaypointDotRadius * f, kWaypointDotLaneShare * style.lane_spacing_pixels);
  style.waypoint_dot_radius = radius >= kMinWaypointDotRadius ? radius : 0.0;

  const double wanted = arrow_spacing > 0.0 ? std::max(arrow_spacing * ppm, kMinArrowSpacingPixels)
                                            : kDefaultArrowSpacingPixels * f;
  // n arrows of about length x half width each on path_pixels: n = path_pixels / spacing.
  const double arrow_area = style.arrow_length * style.arrow_length * kArrowHalfWidthShare;
  const double sparsest =
      free_pixels > 0.0 ? path_pixels * arrow_area / (kMaxArrowAreaShare * free_pixels) : 0.0;
  style.arrow_spacing_pixels = std::max(wanted, sparsest);
  return style;
}

}  // namespace kinematic_coverage::core
