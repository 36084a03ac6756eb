#pragma once

#include "trajectory_generation_tools/plot/coverage_plot.h"
#include "trajectory_generation_tools/plot/plot_canvas.h"

namespace kinematic_coverage::core {

/// Draws the scale bar and, when `data.north_direction` is set, a north arrow turned to it,
/// each small on a semi-opaque white backing in a corner of the box, the corners chosen
/// where they hide the least of the free area, the paths, the start and the goal.
void drawMapOverlays(cairo_t* cr, const CoveragePlotLayout& layout, const CoveragePlotData& data,
                     const PlotScale& scale);

}  // namespace kinematic_coverage::core
