#include "trajectory_generation_tools/replanning/raster_contours.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// A grid vertex (column, row of the cell corner) packed into one key.
std::uint64_t key(int column, int row) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(row)) << 32) |
         static_cast<std::uint32_t>(column);
}

/// Directions of boundary edges: +x, +y, -x, -y (counter-clockwise order).
constexpr int kDx[4] = {1, 0, -1, 0};
constexpr int kDy[4] = {0, 1, 0, -1};

struct Edge {
  int column;
  int row;
  int direction;
  bool used = false;
};

/// Every cell side between a set and an unset cell, directed with the set cell on its
/// left (outer boundaries run counter-clockwise, hole boundaries clockwise), and the
/// edges leaving each grid vertex.
struct BoundaryEdges {
  std::vector<Edge> edges;
  std::unordered_multimap<std::uint64_t, std::size_t> outgoing;
};

BoundaryEdges boundaryEdges(const CoverageRaster& raster, const CellMask& mask) {
  const int rows = raster.rows();
  const int columns = raster.columns();
  auto set = [&](int row, int column) {
    return row >= 0 && row < rows && column >= 0 && column < columns &&
           mask[raster.index(row, column)] != 0;
  };
  BoundaryEdges boundary;
  auto add = [&](int column, int row, int direction) {
    boundary.outgoing.emplace(key(column, row), boundary.edges.size());
    boundary.edges.push_back({column, row, direction});
  };
  for (int row = 0; row < rows; ++row) {
    for (int column = 0; column < columns; ++column) {
      if (!set(row, column)) continue;
      if (!set(row - 1, column)) add(column, row, 0);
      if (!set(row, column + 1)) add(column + 1, row, 1);
      if (!set(row + 1, column)) add(column + 1, row + 1, 2);
      if (!set(row, column - 1)) add(column, row + 1, 3);
    }
  }
  return boundary;
}

/// The grid vertices of the closed ring that starts with edge `first`, marking its edges
/// used. Where two rings meet at a vertex (cells touching at a corner), the left turn
/// keeps each ring around its own cells.
std::vector<std::pair<int, int>> traceRing(BoundaryEdges& boundary, std::size_t first) {
  std::vector<Edge>& edges = boundary.edges;
  std::vector<std::pair<int, int>> corners;
  std::size_t current = first;
  while (!edges[current].used) {
    Edge& edge = edges[current];
    edge.used = true;
    corners.emplace_back(edge.column, edge.row);
    const int end_column = edge.column + kDx[edge.direction];
    const int end_row = edge.row + kDy[edge.direction];
    std::size_t next = current;
    int best_turn = 4;
    const auto range = boundary.outgoing.equal_range(key(end_column, end_row));
    for (auto it = range.first; it != range.second; ++it) {
      const Edge& candidate = edges[it->second];
      if (candidate.used && it->second != first) continue;
      // 1: left turn, 0: straight, 3: right turn (counter-clockwise quarter turns).
      const int turn = (candidate.direction - edge.direction + 4) % 4;
      const int rank = turn == 1 ? 0 : turn == 0 ? 1 : 2;
      if (rank < best_turn) {
        best_turn = rank;
        next = it->second;
      }
    }
    if (next == current) break;
    current = next;
  }
  return corners;
}

/// The ring's corners in metres: a vertex where the direction does not change is dropped.
Ring cornerRing(const CoverageRaster& raster, const std::vector<std::pair<int, int>>& corners) {
  Ring ring;
  const std::size_t n = corners.size();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& previous = corners[(i + n - 1) % n];
    const auto& here = corners[i];
    const auto& after = corners[(i + 1) % n];
    const int cross_value = (here.first - previous.first) * (after.second - here.second) -
                            (here.second - previous.second) * (after.first - here.first);
    if (cross_value == 0) continue;
    ring.emplace_back(raster.origin().x() + here.first * raster.cellSize(),
                      raster.origin().y() + here.second * raster.cellSize());
  }
  return ring;
}

/// Polygons of the outer rings, each hole given to the smallest outer ring around a point
/// just outside it (a quarter cell off its first edge).
std::vector<PolygonWithHoles> withHoles(std::vector<Ring> outer, std::vector<Ring> holes,
                                        double cell_size) {
  std::vector<PolygonWithHoles> polygons;
  std::vector<double> areas;
  for (Ring& ring : outer) {
    areas.push_back(signedArea(ring));
    polygons.push_back({std::move(ring), {}});
  }
  for (Ring& hole : holes) {
    const Point2 a = hole[0];
    const Point2 b = hole[1];
    const Point2 along = (b - a).normalized();
    const Point2 probe = 0.5 * (a + b) + 0.25 * cell_size * Point2(-along.y(), along.x());
    std::size_t owner = polygons.size();
    for (std::size_t k = 0; k < polygons.size(); ++k) {
      if (insideRing(probe, polygons[k].hull) &&
          (owner == polygons.size() || areas[k] < areas[owner])) {
        owner = k;
      }
    }
    if (owner < polygons.size()) polygons[owner].holes.push_back(std::move(hole));
  }
  return polygons;
}

}  // namespace

std::vector<PolygonWithHoles> traceMaskContours(const CoverageRaster& raster,
                                                const CellMask& mask) {
  if (mask.size() != raster.cellCount()) {
    throw InvalidInputError("mask contours: the mask does not match the raster");
  }
  BoundaryEdges boundary = boundaryEdges(raster, mask);
  std::vector<Ring> outer;
  std::vector<Ring> holes;
  for (std::size_t first = 0; first < boundary.edges.size(); ++first) {
    if (boundary.edges[first].used) continue;
    Ring ring = cornerRing(raster, traceRing(boundary, first));
    if (ring.size() < 3) continue;
    (signedArea(ring) > 0.0 ? outer : holes).push_back(std::move(ring));
  }
  return withHoles(std::move(outer), std::move(holes), raster.cellSize());
}

std::size_t removeDiagonalPinches(const CoverageRaster& raster, CellMask& mask) {
  if (mask.size() != raster.cellCount()) {
    throw InvalidInputError("mask pinches: the mask does not match the raster");
  }
  const int rows = raster.rows();
  const int columns = raster.columns();
  auto set = [&](int row, int column) {
    return row >= 0 && row < rows && column >= 0 && column < columns &&
           mask[raster.index(row, column)] != 0;
  };
  std::size_t cleared = 0;
  bool changed = true;
  while (changed) {
    changed = false;
    for (int row = 0; row + 1 < rows; ++row) {
      for (int column = 0; column + 1 < columns; ++column) {
        const bool bottom_left = set(row, column);
        const bool bottom_right = set(row, column + 1);
        const bool top_left = set(row + 1, column);
        const bool top_right = set(row + 1, column + 1);
        if (bottom_left && top_right && !bottom_right && !top_left) {
          mask[raster.index(row + 1, column + 1)] = 0;
        } else if (bottom_right && top_left && !bottom_left && !top_right) {
          mask[raster.index(row + 1, column)] = 0;
        } else {
          continue;
        }
        ++cleared;
        changed = true;
      }
    }
  }
  return cleared;
}

}  // namespace kinematic_coverage::core
