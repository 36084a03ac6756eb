#include "trajectory_generation_tools/trajectory/primitive_path_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "trajectory_generation_tools/trajectory/primitive_distance.h"

namespace kinematic_coverage::core {
namespace {

/// An axis-aligned box, for a cheap lower bound on distances.
struct Box {
  Point2 low;
  Point2 high;
};

Box boxOf(const Point2& a, const Point2& b) { return {a.cwiseMin(b), a.cwiseMax(b)}; }

/// A box holding the primitive (an arc's whole circle, a clothoid's chords grown by their
/// tolerance; enough for pruning).
Box boxOf(const PathPrimitive& primitive) {
  if (primitive.kind() == PrimitiveKind::kArc) {
    const Point2 extent = Point2::Constant(primitive.radius());
    return {primitive.centre() - extent, primitive.centre() + extent};
  }
  if (primitive.kind() == PrimitiveKind::kClothoid) {
    Box box = boxOf(primitive.start(), primitive.end());
    for (const Point2& p : primitive.polyline(kClothoidDistanceTolerance)) {
      box.low = box.low.cwiseMin(p);
      box.high = box.high.cwiseMax(p);
    }
    box.low -= Point2::Constant(kClothoidDistanceTolerance);
    box.high += Point2::Constant(kClothoidDistanceTolerance);
    return box;
  }
  return boxOf(primitive.start(), primitive.end());
}

double boxDistance(const Box& a, const Box& b) {
  const Point2 gap = (a.low - b.high).cwiseMax(b.low - a.high).cwiseMax(0.0);
  return gap.norm();
}

struct Edge {
  Point2 a;
  Point2 b;
  Box box;
};

void appendEdges(const Ring& ring, std::vector<Edge>& edges) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point2& a = ring[i];
    const Point2& b = ring[(i + 1) % ring.size()];
    edges.push_back({a, b, boxOf(a, b)});
  }
}

}  // namespace

double primitivePathLength(const std::vector<PathPrimitive>& path) {
  double length = 0.0;
  for (const PathPrimitive& primitive : path) length += primitive.length();
  return length;
}

double primitivePathMaxCurvature(const std::vector<PathPrimitive>& path) {
  double curvature = 0.0;
  for (const PathPrimitive& primitive : path) {
    if (primitive.kind() != PrimitiveKind::kRotation) {
      curvature = std::max(curvature, primitive.curvature());
    }
  }
  return curvature;
}

double primitivePathClearance(const std::vector<PathPrimitive>& path,
                              const PolygonWithHoles& free_area) {
  std::vector<Edge> edges;
  appendEdges(free_area.hull, edges);
  for (const Ring& hole : free_area.holes) appendEdges(hole, edges);

  double clearance = std::numeric_limits<double>::infinity();
  for (const PathPrimitive& primitive : path) {
    const Box box = boxOf(primitive);
    for (const Edge& edge : edges) {
      if (boxDistance(box, edge.box) >= clearance) continue;
      clearance = std::min(clearance, distancePrimitiveToSegment(primitive, edge.a, edge.b));
    }
  }
  return clearance;
}

}  // namespace kinematic_coverage::core
