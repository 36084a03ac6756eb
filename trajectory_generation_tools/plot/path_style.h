#pragma once

#include "trajectory_generation_tools/plot/coverage_plot.h"
#include "trajectory_generation_tools/plot/plot_canvas.h"

namespace kinematic_coverage::core {

/// Nominal sizes of the paths, pixels at the base image size (multiplied by the
/// PlotScale factor): what a small map, whose lanes are far apart on the image, shows.
inline constexpr double kNominalTrajectoryWidth = 1.8;
inline constexpr double kNominalWaypointWidth = 1.3;
inline constexpr double kNominalOffsetOutlineWidth = 1.1;
inline constexpr double kNominalArrowLength = 12.0;
inline constexpr double kNominalWaypointDotRadius = 2.8;
/// Default on-image distance between heading arrows, pixels at the base image size.
inline constexpr double kDefaultArrowSpacingPixels = 100.0;
/// An arrowhead's half width as a share of its length.
inline constexpr double kArrowHalfWidthShare = 0.375;

/// How to draw the paths of `data` on `layout`: widths and marker sizes from the lane
/// spacing on the image (CoveragePlotPathStyle), arrows every `arrow_spacing` metres
/// (0: the default on-image spacing).
CoveragePlotPathStyle pathStyleFor(const CoveragePlotLayout& layout, const CoveragePlotData& data,
                                   double arrow_spacing, const PlotScale& scale);

}  // namespace kinematic_coverage::core
