#include "coverage_system/mission/polygon_sketch.h"

#include <cstddef>
#include <stdexcept>
#include <utility>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/validation/polygon_validator.h"

namespace kinematic_coverage::core {
namespace {

/// A closed ring needs this many vertices; with fewer it is removed.
constexpr std::size_t kMinRingVertices = 3;

}  // namespace

void PolygonSketch::addVertex(const Point2& point) { open_.push_back(point); }

bool PolygonSketch::closeRing() {
  if (open_.size() < kMinRingVertices) return false;
  if (hull_.empty()) {
    hull_ = std::move(open_);
  } else {
    holes_.push_back(std::move(open_));
  }
  open_.clear();
  return true;
}

void PolygonSketch::cancelOpenRing() { open_.clear(); }

void PolygonSketch::moveVertex(const VertexId& vertex, const Point2& point) {
  ring(vertex).at(vertex.index) = point;
}

void PolygonSketch::deleteVertex(const VertexId& vertex) {
  Ring& points = ring(vertex);
  if (vertex.index >= points.size()) throw std::out_of_range("PolygonSketch: no such vertex");
  points.erase(points.begin() + static_cast<std::ptrdiff_t>(vertex.index));
  if (vertex.ring == RingKind::kOpen || points.size() >= kMinRingVertices) return;
  if (vertex.ring == RingKind::kHull) {
    hull_.clear();
  } else {
    holes_.erase(holes_.begin() + static_cast<std::ptrdiff_t>(vertex.hole));
  }
}

std::optional<PolygonSketch::VertexId> PolygonSketch::nearestVertex(const Point2& point,
                                                                    double tolerance) const {
  std::optional<VertexId> nearest;
  double nearest_distance = tolerance;
  const auto consider = [&](const Ring& points, RingKind kind, std::size_t hole) {
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double distance = (points[i] - point).norm();
      if (distance < nearest_distance || (!nearest && distance <= nearest_distance)) {
        nearest = VertexId{kind, hole, i};
        nearest_distance = distance;
      }
    }
  };
  consider(hull_, RingKind::kHull, 0);
  for (std::size_t h = 0; h < holes_.size(); ++h) consider(holes_[h], RingKind::kHole, h);
  consider(open_, RingKind::kOpen, 0);
  return nearest;
}

const Point2& PolygonSketch::vertex(const VertexId& vertex) const {
  return ring(vertex).at(vertex.index);
}

std::optional<std::string> PolygonSketch::validity() const {
  if (hull_.empty()) return std::string("no hull yet: click its vertices, then close the ring");
  try {
    PolygonValidator().validate(PolygonWithHoles{hull_, holes_});
  } catch (const InvalidInputError& error) {
    return std::string(error.what());
  }
  return std::nullopt;
}

std::optional<PolygonWithHoles> PolygonSketch::completePolygon() const {
  if (!open_.empty() || validity()) return std::nullopt;
  return PolygonWithHoles{hull_, holes_};
}

Ring& PolygonSketch::ring(const VertexId& vertex) {
  return const_cast<Ring&>(std::as_const(*this).ring(vertex));
}

const Ring& PolygonSketch::ring(const VertexId& vertex) const {
  switch (vertex.ring) {
    case RingKind::kHull:
      return hull_;
    case RingKind::kHole:
      return holes_.at(vertex.hole);
    case RingKind::kOpen:
      break;
  }
  return open_;
}

}  // namespace kinematic_coverage::core
