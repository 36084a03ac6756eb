#include "trajectory_generation_tools/coverage/reachable_area.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {
namespace {

void requireSize(const CoverageRaster& raster, const CellMask& mask, const char* what) {
  if (mask.size() != raster.cellCount()) {
    std::ostringstream message;
    message << "coverage raster: the " << what << " mask has " << mask.size() << " cells, the grid "
            << raster.cellCount();
    throw InvalidInputError(message.str());
  }
}

/// Lower envelope of the parabolas (x - q)^2 + f(q) over the sample positions q
/// (Felzenszwalb and Huttenlocher, "Distance Transforms of Sampled Functions", 2012).
class ParabolaEnvelope {
 public:
  /// Builds the envelope; `positions` ascending, `heights` the f(q) there (not empty).
  void build(const std::vector<int>& positions, const std::vector<double>& heights) {
    const std::size_t n = positions.size();
    apex_.assign(n, 0);
    bound_.assign(n + 1, 0.0);
    std::size_t k = 0;
    apex_[0] = 0;
    bound_[0] = -std::numeric_limits<double>::infinity();
    bound_[1] = std::numeric_limits<double>::infinity();
    for (std::size_t q = 1; q < n; ++q) {
      double s = intersection(positions, heights, apex_[k], q);
      while (s <= bound_[k]) {
        --k;
        s = intersection(positions, heights, apex_[k], q);
      }
      ++k;
      apex_[k] = q;
      bound_[k] = s;
      bound_[k + 1] = std::numeric_limits<double>::infinity();
    }
    positions_ = &positions;
    heights_ = &heights;
    segment_ = 0;
  }

  /// The envelope's value at x; successive calls must come with ascending x.
  double valueAt(int x) {
    while (bound_[segment_ + 1] < x) ++segment_;
    const std::size_t q = apex_[segment_];
    const double dx = x - (*positions_)[q];
    return dx * dx + (*heights_)[q];
  }

 private:
  static double intersection(const std::vector<int>& positions, const std::vector<double>& heights,
                             std::size_t p, std::size_t q) {
    const double xp = positions[p];
    const double xq = positions[q];
    return ((heights[q] + xq * xq) - (heights[p] + xp * xp)) / (2.0 * (xq - xp));
  }

  std::vector<std::size_t> apex_;
  std::vector<double> bound_;
  const std::vector<int>* positions_ = nullptr;
  const std::vector<double>* heights_ = nullptr;
  std::size_t segment_ = 0;
};

/// The two passes of dilateMask with vertical distances stored as `Distance`, an integer
/// type that holds `cap`, so that the distance grid stays small.
template <typename Distance>
CellMask dilateWithin(const CoverageRaster& raster, const CellMask& mask, int cap, double reach) {
  const int columns = raster.columns();
  const int rows = raster.rows();
  const double reach_squared = reach * reach;
  const int reach_columns = static_cast<int>(std::min(reach, static_cast<double>(columns)));

  // Pass 1, along the columns (row by row, so memory is read in order): cells to the
  // nearest set cell in the same column, capped.
  std::vector<Distance> vertical(raster.cellCount(), static_cast<Distance>(cap));
  for (int row = 0; row < rows; ++row) {
    for (int column = 0; column < columns; ++column) {
      const std::size_t i = raster.index(row, column);
      if (mask[i] != 0) {
        vertical[i] = Distance{0};
      } else if (row > 0) {
        vertical[i] = static_cast<Distance>(
            std::min(vertical[i - static_cast<std::size_t>(columns)] + 1, cap));
      }
    }
  }
  for (int row = rows - 2; row >= 0; --row) {
    for (int column = 0; column < columns; ++column) {
      const std::size_t i = raster.index(row, column);
      vertical[i] = static_cast<Distance>(
          std::min<int>(vertical[i], vertical[i + static_cast<std::size_t>(columns)] + 1));
    }
  }

  // Pass 2, along the rows: the squared distance is the lower envelope of the parabolas
  // (column - q)^2 + vertical(q)^2 over the columns q with a set cell within reach. Cells
  // with vertical 0 are set; inside a run of them only the run's ends can be nearest to a
  // cell outside the run, so the parabolas of the run's inside are left out.
  CellMask grown(raster.cellCount(), 0);
  std::vector<int> positions;
  std::vector<double> heights;
  ParabolaEnvelope envelope;
  for (int row = 0; row < rows; ++row) {
    const Distance* line = vertical.data() + raster.index(row, 0);
    positions.clear();
    heights.clear();
    bool any_unset = false;
    for (int column = 0; column < columns; ++column) {
      const int v = line[column];
      any_unset = any_unset || v != 0;
      if (v >= cap) continue;
      const bool run_inside = v == 0 && column > 0 && column + 1 < columns &&
                              line[column - 1] == 0 && line[column + 1] == 0;
      if (run_inside) continue;
      positions.push_back(column);
      heights.push_back(static_cast<double>(v) * v);
    }
    std::uint8_t* out = grown.data() + raster.index(row, 0);
    for (int column = 0; column < columns; ++column) out[column] = line[column] == 0 ? 1 : 0;
    if (!any_unset || positions.empty()) continue;
    envelope.build(positions, heights);
    const int first = std::max(0, positions.front() - reach_columns);
    const int last = std::min(columns - 1, positions.back() + reach_columns);
    for (int column = first; column <= last; ++column) {
      if (line[column] != 0 && envelope.valueAt(column) <= reach_squared) out[column] = 1;
    }
  }
  return grown;
}

}  // namespace

CellMask dilateMask(const CoverageRaster& raster, const CellMask& mask, double radius) {
  requireSize(raster, mask, "dilated");
  if (!(radius >= 0.0) || !std::isfinite(radius)) {
    std::ostringstream message;
    message << "coverage raster: dilation radius " << radius << " must be finite and >= 0";
    throw InvalidInputError(message.str());
  }
  if (radius == 0.0) return mask;
  const double reach = radius / raster.cellSize() + 0.5;  // in cells, centre to centre
  // Vertical distances of `cap` cells or more are out of reach; capping keeps them small.
  const int cap =
      static_cast<int>(std::min(std::floor(reach) + 1.0, static_cast<double>(raster.rows())));
  if (cap <= std::numeric_limits<std::uint8_t>::max()) {
    return dilateWithin<std::uint8_t>(raster, mask, cap, reach);
  }
  if (cap <= std::numeric_limits<std::uint16_t>::max()) {
    return dilateWithin<std::uint16_t>(raster, mask, cap, reach);
  }
  return dilateWithin<std::int32_t>(raster, mask, cap, reach);
}

CellMask reachableArea(const CoverageRaster& raster, const CellMask& free_area,
                       const CellMask& offset_free_area, double footprint_length) {
  requireSize(raster, free_area, "free area");
  requireSize(raster, offset_free_area, "offset free area");
  if (!(footprint_length >= 0.0) || !std::isfinite(footprint_length)) {
    std::ostringstream message;
    message << "coverage: footprint length " << footprint_length << " must be finite and >= 0";
    throw InvalidInputError(message.str());
  }
  CellMask reachable = dilateMask(raster, offset_free_area, 0.5 * footprint_length);
  for (std::size_t i = 0; i < reachable.size(); ++i) {
    reachable[i] = (reachable[i] != 0 && free_area[i] != 0) ? 1 : 0;
  }
  return reachable;
}

}  // namespace kinematic_coverage::core
