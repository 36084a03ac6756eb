#include "trajectory_generation_tools/trajectory/primitive_path_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "trajectory_generation_tools/trajectory/primitive_distance.h"

namespace kinematic_coverage::core {
namespace {

/// m: spacing of the points of the nearest primitive searched for the closest approach.
constexpr double kClosestPointSpacing = 0.01;
/// Upper bound on those points (a primitive longer than 100 m is searched more coarsely).
constexpr int kMaxClosestPointSteps = 10000;

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

ClosestApproach primitivePathClosestApproach(const std::vector<PathPrimitive>& path,
                                             const PolygonWithHoles& free_area) {
  std::vector<Edge> edges;
  appendEdges(free_area.hull, edges);
  for (const Ring& hole : free_area.holes) appendEdges(hole, edges);

  double clearance = std::numeric_limits<double>::infinity();
  const PathPrimitive* nearest_primitive = nullptr;
  const Edge* nearest_edge = nullptr;
  for (const PathPrimitive& primitive : path) {
    const Box box = boxOf(primitive);
    for (const Edge& edge : edges) {
      if (boxDistance(box, edge.box) >= clearance) continue;
      const double distance = distancePrimitiveToSegment(primitive, edge.a, edge.b);
      if (distance < clearance) {
        clearance = distance;
        nearest_primitive = &primitive;
        nearest_edge = &edge;
      }
    }
  }
  ClosestApproach approach{clearance, Point2::Zero()};
  if (nearest_primitive == nullptr) return approach;
  // The nearest primitive's points kClosestPointSpacing apart, at most kMaxClosestPointSteps.
  const int steps =
      std::clamp(static_cast<int>(std::ceil(nearest_primitive->length() / kClosestPointSpacing)), 1,
                 kMaxClosestPointSteps);
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= steps; ++i) {
    const Point2 p = nearest_primitive->poseAt(static_cast<double>(i) / steps).position();
    const double distance = distanceToSegment(p, nearest_edge->a, nearest_edge->b);
    if (distance < best) {
      best = distance;
      approach.point = p;
    }
  }
  return approach;
}

double primitivePathClearance(const std::vector<PathPrimitive>& path,
                              const PolygonWithHoles& free_area) {
  return primitivePathClosestApproach(path, free_area).distance_m;
}

}  // namespace kinematic_coverage::core
