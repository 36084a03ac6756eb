#include "polygon_coverage_ros_bridge/sweeps/reachable_area.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <utility>
#include <vector>

#include "polygon_coverage_ros_bridge/base/parallel_for.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

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

/// The edges of polygons in square buckets at least `reach` wide, for the question whether
/// a point lies within `reach` of an edge: only the buckets around the point are searched.
class EdgeBuckets {
 public:
  EdgeBuckets(const std::vector<PolygonWithHoles>& polygons, double reach) : reach_(reach) {
    Point2 low = Point2::Constant(std::numeric_limits<double>::infinity());
    Point2 high = -low;
    const auto addRing = [&](const Ring& ring) {
      for (std::size_t i = 0; i < ring.size(); ++i) {
        edges_.emplace_back(ring[i], ring[(i + 1) % ring.size()]);
        low = low.cwiseMin(ring[i]);
        high = high.cwiseMax(ring[i]);
      }
    };
    for (const PolygonWithHoles& polygon : polygons) {
      addRing(polygon.hull);
      for (const Ring& hole : polygon.holes) addRing(hole);
    }
    if (edges_.empty()) return;
    origin_ = low;
    const Point2 extent = high - low;
    // Buckets no smaller than the reach, and no more of them than about four per edge.
    size_ = std::max({reach, 1e-9, std::sqrt(extent.x() * extent.y() / (4.0 * edges_.size()))});
    columns_ = static_cast<int>(extent.x() / size_) + 1;
    rows_ = static_cast<int>(extent.y() / size_) + 1;
    buckets_.resize(static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_));
    for (std::size_t e = 0; e < edges_.size(); ++e) {
      const auto& [a, b] = edges_[e];
      const int c0 = column(std::min(a.x(), b.x()));
      const int c1 = column(std::max(a.x(), b.x()));
      const int r0 = row(std::min(a.y(), b.y()));
      const int r1 = row(std::max(a.y(), b.y()));
      for (int r = r0; r <= r1; ++r) {
        for (int c = c0; c <= c1; ++c) {
          // Only the buckets the edge passes near (within half a bucket diagonal).
          const Point2 centre = origin_ + size_ * Point2(c + 0.5, r + 0.5);
          if (distanceToSegment(centre, a, b) > size_) continue;
          buckets_[bucket(r, c)].push_back(static_cast<std::uint32_t>(e));
        }
      }
    }
  }

  /// True when p lies within the reach of an edge.
  bool near(const Point2& p) const {
    if (edges_.empty()) return false;
    const int c0 = column(p.x() - reach_);
    const int c1 = column(p.x() + reach_);
    const int r0 = row(p.y() - reach_);
    const int r1 = row(p.y() + reach_);
    for (int r = r0; r <= r1; ++r) {
      for (int c = c0; c <= c1; ++c) {
        for (std::uint32_t e : buckets_[bucket(r, c)]) {
          if (distanceToSegment(p, edges_[e].first, edges_[e].second) <= reach_) return true;
        }
      }
    }
    return false;
  }

 private:
  int column(double x) const {
    return std::clamp(static_cast<int>(std::floor((x - origin_.x()) / size_)), 0, columns_ - 1);
  }
  int row(double y) const {
    return std::clamp(static_cast<int>(std::floor((y - origin_.y()) / size_)), 0, rows_ - 1);
  }
  std::size_t bucket(int r, int c) const {
    return static_cast<std::size_t>(r) * static_cast<std::size_t>(columns_) +
           static_cast<std::size_t>(c);
  }

  double reach_;
  std::vector<std::pair<Point2, Point2>> edges_;
  Point2 origin_ = Point2::Zero();
  double size_ = 1.0;
  int columns_ = 1;
  int rows_ = 1;
  std::vector<std::vector<std::uint32_t>> buckets_;
};

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

/// Grid cells from which the distance transform and the reachable area's rim are computed
/// on every hardware thread.
constexpr std::size_t kParallelGridCells = 250'000;

/// Calls body(first, end) for `count` items (rows or columns) cut into one block per
/// thread, the blocks on every hardware thread for grids of kParallelGridCells or more
/// (the distance transform's passes, the reachable area's rim).
template <typename Body>
void forEachBlock(const CoverageRaster& raster, int count, Body&& body) {
  const std::size_t threads =
      raster.cellCount() >= kParallelGridCells ? parallelThreadCount(raster.cellCount()) : 1;
  parallelForOnThreads(threads, threads, [&](std::size_t block, std::size_t) {
    body(static_cast<int>(static_cast<long long>(count) * block / threads),
         static_cast<int>(static_cast<long long>(count) * (block + 1) / threads));
  });
}

/// Pass 1 of dilateMask, along the columns (row by row, so memory is read in order): cells
/// to the nearest set cell in the same column, capped at `cap`; blocks of columns apart.
template <typename Distance>
std::vector<Distance> verticalDistances(const CoverageRaster& raster, const CellMask& mask,
                                        int cap) {
  const int columns = raster.columns();
  const int rows = raster.rows();
  std::vector<Distance> vertical(raster.cellCount(), static_cast<Distance>(cap));
  forEachBlock(raster, columns, [&](int first_column, int end_column) {
    for (int row = 0; row < rows; ++row) {
      for (int column = first_column; column < end_column; ++column) {
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
      for (int column = first_column; column < end_column; ++column) {
        const std::size_t i = raster.index(row, column);
        vertical[i] = static_cast<Distance>(
            std::min<int>(vertical[i], vertical[i + static_cast<std::size_t>(columns)] + 1));
      }
    }
  });
  return vertical;
}

/// The two passes of dilateMask with vertical distances stored as `Distance`, an integer
/// type that holds `cap`, so that the distance grid stays small: one mask per reach (in
/// cells, centre to centre; `cap` beyond the largest), all from the same distances.
template <typename Distance>
std::vector<CellMask> dilateWithin(const CoverageRaster& raster, const CellMask& mask, int cap,
                                   const std::vector<double>& reaches) {
  const int columns = raster.columns();
  const double largest = *std::max_element(reaches.begin(), reaches.end());
  const int reach_columns = static_cast<int>(std::min(largest, static_cast<double>(columns)));
  const std::vector<Distance> vertical = verticalDistances<Distance>(raster, mask, cap);

  // Pass 2, along the rows (blocks of rows apart): the squared distance is the lower envelope
  // of the parabolas (column - q)^2 + vertical(q)^2 over the columns q with a set cell within
  // reach. Cells with vertical 0 are set; inside a run of them only the run's ends can be
  // nearest to a cell outside the run, so the parabolas of the run's inside are left out.
  std::vector<CellMask> grown(reaches.size(), CellMask(raster.cellCount(), 0));
  std::vector<double> reaches_squared;
  for (double reach : reaches) reaches_squared.push_back(reach * reach);
  forEachBlock(raster, raster.rows(), [&](int first_row, int end_row) {
    std::vector<int> positions;
    std::vector<double> heights;
    ParabolaEnvelope envelope;
    for (int row = first_row; row < end_row; ++row) {
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
      for (CellMask& out : grown) {
        std::uint8_t* out_row = out.data() + raster.index(row, 0);
        for (int column = 0; column < columns; ++column) {
          out_row[column] = line[column] == 0 ? 1 : 0;
        }
      }
      if (!any_unset || positions.empty()) continue;
      envelope.build(positions, heights);
      const int first = std::max(0, positions.front() - reach_columns);
      const int last = std::min(columns - 1, positions.back() + reach_columns);
      const std::size_t row_start = raster.index(row, 0);
      for (int column = first; column <= last; ++column) {
        if (line[column] == 0) continue;
        const double value = envelope.valueAt(column);
        for (std::size_t k = 0; k < grown.size(); ++k) {
          if (value <= reaches_squared[k]) grown[k][row_start + column] = 1;
        }
      }
    }
  });
  return grown;
}

/// dilateMask by a disc stamped around each set cell: the same masks (a cell within reach,
/// centre to centre in cells, of a set cell), in time of the set cells times the disc, for
/// masks of few set cells (unseen slivers) on large grids.
std::vector<CellMask> dilateByDiscs(const CoverageRaster& raster, const CellMask& mask,
                                    const std::vector<std::size_t>& set_cells,
                                    const std::vector<double>& reaches) {
  const int columns = raster.columns();
  const int rows = raster.rows();
  std::vector<CellMask> grown;
  for (double reach : reaches) {
    CellMask out = mask;
    const double reach_squared = reach * reach;
    const int reach_rows = static_cast<int>(std::floor(reach));
    for (std::size_t i : set_cells) {
      const int row = static_cast<int>(i / static_cast<std::size_t>(columns));
      const int column = static_cast<int>(i % static_cast<std::size_t>(columns));
      for (int dy = -reach_rows; dy <= reach_rows; ++dy) {
        const int r = row + dy;
        if (r < 0 || r >= rows) continue;
        const long long dy_squared = static_cast<long long>(dy) * dy;
        int dx = static_cast<int>(std::sqrt(std::max(0.0, reach_squared - dy_squared)));
        while (static_cast<double>((dx + 1LL) * (dx + 1) + dy_squared) <= reach_squared) ++dx;
        while (dx >= 0 &&
               static_cast<double>(static_cast<long long>(dx) * dx + dy_squared) > reach_squared) {
          --dx;
        }
        if (dx < 0) continue;
        const int first = std::max(0, column - dx);
        const int last = std::min(columns - 1, column + dx);
        std::uint8_t* line = out.data() + raster.index(r, 0);
        std::fill(line + first, line + last + 1, std::uint8_t{1});
      }
    }
    grown.push_back(std::move(out));
  }
  return grown;
}

}  // namespace

CellMask dilateMask(const CoverageRaster& raster, const CellMask& mask, double radius) {
  return std::move(dilateMask(raster, mask, std::vector<double>{radius}).front());
}

std::vector<CellMask> dilateMask(const CoverageRaster& raster, const CellMask& mask,
                                 const std::vector<double>& radii) {
  requireSize(raster, mask, "dilated");
  std::vector<double> reaches;  // of the positive radii, in cells, centre to centre
  for (double radius : radii) {
    if (!(radius >= 0.0) || !std::isfinite(radius)) {
      std::ostringstream message;
      message << "coverage raster: dilation radius " << radius << " must be finite and >= 0";
      throw InvalidInputError(message.str());
    }
    if (radius > 0.0) reaches.push_back(radius / raster.cellSize() + 0.5);
  }
  std::vector<CellMask> grown;
  if (!reaches.empty()) {
    const double largest = *std::max_element(reaches.begin(), reaches.end());
    // Few set cells: a disc around each costs less than the transform's passes over the grid.
    const double disc = (2.0 * std::floor(largest) + 1.0) * (2.0 * std::floor(largest) + 1.0);
    const double stamp_budget = static_cast<double>(raster.cellCount()) / disc;
    std::vector<std::size_t> set_cells;
    for (std::size_t i = 0;
         i < mask.size() && static_cast<double>(set_cells.size()) <= stamp_budget; ++i) {
      if (mask[i] != 0) set_cells.push_back(i);
    }
    if (static_cast<double>(set_cells.size()) <= stamp_budget) {
      grown = dilateByDiscs(raster, mask, set_cells, reaches);
    }
  }
  if (!reaches.empty() && grown.empty()) {
    // Vertical distances of `cap` cells or more are out of every reach; capping keeps them
    // small.
    const double largest = *std::max_element(reaches.begin(), reaches.end());
    const int cap =
        static_cast<int>(std::min(std::floor(largest) + 1.0, static_cast<double>(raster.rows())));
    if (cap <= std::numeric_limits<std::uint8_t>::max()) {
      grown = dilateWithin<std::uint8_t>(raster, mask, cap, reaches);
    } else if (cap <= std::numeric_limits<std::uint16_t>::max()) {
      grown = dilateWithin<std::uint16_t>(raster, mask, cap, reaches);
    } else {
      grown = dilateWithin<std::int32_t>(raster, mask, cap, reaches);
    }
  }
  // Radius 0 gives the mask itself.
  std::vector<CellMask> result;
  std::size_t next = 0;
  for (double radius : radii) result.push_back(radius > 0.0 ? std::move(grown[next++]) : mask);
  return result;
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

CellMask reachableArea(const CoverageRaster& raster, const CellMask& free_area,
                       const CellMask& offset_free_area,
                       const std::vector<PolygonWithHoles>& offset_parts, double footprint_length) {
  const double reach = 0.5 * footprint_length;
  if (reach == 0.0) return reachableArea(raster, free_area, offset_free_area, footprint_length);
  requireSize(raster, free_area, "free area");
  requireSize(raster, offset_free_area, "offset free area");
  if (!std::isfinite(reach) || reach < 0.0) {
    std::ostringstream message;
    message << "coverage: footprint length " << footprint_length << " must be finite and >= 0";
    throw InvalidInputError(message.str());
  }
  // Grown by a cell less, every cell's centre lies within the reach of a set cell's centre
  // (inside the polygons); grown by a cell more, the cells left out lie farther than the
  // reach plus three quarters of a cell from the polygons (every point of which lies within
  // half a cell diagonal of a set cell's centre). Only the cells between are measured. The
  // three from one distance transform.
  const double cell = raster.cellSize();
  std::vector<CellMask> grown =
      dilateMask(raster, offset_free_area, {reach, std::max(0.0, reach - cell), reach + cell});
  CellMask reachable = std::move(grown[0]);
  for (std::size_t i = 0; i < reachable.size(); ++i) {
    reachable[i] = (reachable[i] != 0 && free_area[i] != 0) ? 1 : 0;
  }
  const CellMask& surely = grown[1];
  const CellMask& maybe = grown[2];
  const EdgeBuckets edges(offset_parts, reach);
  forEachBlock(raster, raster.rows(), [&](int first_row, int end_row) {
    const std::size_t end = raster.index(end_row, 0);
    for (std::size_t i = raster.index(first_row, 0); i < end; ++i) {
      if (free_area[i] == 0 || maybe[i] == 0 || surely[i] != 0) continue;
      reachable[i] = edges.near(raster.cellCentre(i)) ? 1 : 0;
    }
  });
  return reachable;
}

}  // namespace kinematic_coverage::core
