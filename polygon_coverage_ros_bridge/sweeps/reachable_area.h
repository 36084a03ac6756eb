#pragma once

#include <vector>

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "polygon_coverage_ros_bridge/sweeps/coverage_raster.h"

namespace kinematic_coverage::core {

/// The cells within `radius` of the area that the set cells of `mask` stand for: a cell
/// is set when its centre lies within radius + cell_size / 2 of a set cell's centre (the
/// half cell measures from the set cells' edges, so that the grown area is unbiased).
/// Uses the Felzenszwalb-Huttenlocher Euclidean distance transform (linear time in the
/// cells, independent of the radius). Radius 0 returns the mask unchanged.
/// Throws InvalidInputError for a negative or non-finite radius or a mask of the wrong size.
CellMask dilateMask(const CoverageRaster& raster, const CellMask& mask, double radius);

/// dilateMask for each of `radii`, from one distance transform (the same masks as one call
/// per radius, in the time of about one). Throws as above.
std::vector<CellMask> dilateMask(const CoverageRaster& raster, const CellMask& mask,
                                 const std::vector<double>& radii);

/// The reachable area: the free cells within half a footprint
/// length of the offset free area; with a line sensor (length 0) the offset free area.
/// Throws InvalidInputError for a negative or non-finite length or masks of the wrong size.
CellMask reachableArea(const CoverageRaster& raster, const CellMask& free_area,
                       const CellMask& offset_free_area, double footprint_length);

/// The reachable area of the coverage report: the free cells whose centres lie within half
/// a footprint length of the offset free area's polygons `offset_parts` (in the raster's
/// frame; `offset_free_area` is their rasterization). The grown mask above misplaces the
/// rim by up to half a cell either way, so that along a wall a lane sees exactly up to,
/// a thin line of cells beyond what any footprint can reach counted as unseen (0.1 % of a
/// 40 m comb); here the cells near the rim are measured against the polygons' edges.
/// Throws as above.
CellMask reachableArea(const CoverageRaster& raster, const CellMask& free_area,
                       const CellMask& offset_free_area,
                       const std::vector<PolygonWithHoles>& offset_parts, double footprint_length);

}  // namespace kinematic_coverage::core
