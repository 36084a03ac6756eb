#pragma once

#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "polygon_coverage_ros_bridge/sweeps/coverage_raster.h"

namespace kinematic_coverage::core {

/// The set cells of a mask as polygons with holes, exactly (cell edges; collinear
/// vertices dropped): each 4-connected region of set cells is one polygon, its hull
/// counter-clockwise and its holes clockwise. Every ring is simple when the mask has no
/// pinch (see removeDiagonalPinches); a pinch makes a ring touch itself at a corner.
/// Throws InvalidInputError for a mask of the wrong size.
std::vector<PolygonWithHoles> traceMaskContours(const CoverageRaster& raster, const CellMask& mask);

/// Clears set cells until no 2 x 2 block has its set cells on one diagonal only (two set
/// cells touching at a corner between two unset ones), the configuration whose contour
/// pinches. Returns how many cells were cleared. Throws InvalidInputError for a mask of
/// the wrong size.
std::size_t removeDiagonalPinches(const CoverageRaster& raster, CellMask& mask);

}  // namespace kinematic_coverage::core
