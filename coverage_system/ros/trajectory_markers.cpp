#include "coverage_system/ros/trajectory_markers.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

#include "coverage_system/ros/marker_scale.h"
#include "coverage_system/ros/plan_markers.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::nodes {
namespace {

/// Arcs are drawn as chords of at most this angle (rad).
constexpr double kArcDrawingStep = 0.1;
/// Metres a drawn clothoid's chords may stray from it.
constexpr double kClothoidDrawingTolerance = 0.005;

geometry_msgs::Point point(const core::Point2& p) {
  geometry_msgs::Point message;
  message.x = p.x();
  message.y = p.y();
  message.z = 0.02;
  return message;
}

visualization_msgs::Marker lineList(const std::string& ns, const std_msgs::Header& header,
                                    float red, float green, float blue, double width = 0.08) {
  visualization_msgs::Marker marker;
  marker.header = header;
  marker.ns = ns;
  marker.id = 0;
  marker.type = visualization_msgs::Marker::LINE_LIST;
  marker.action = visualization_msgs::Marker::ADD;
  marker.pose.orientation.w = 1.0;
  marker.scale.x = width;
  marker.color.r = red;
  marker.color.g = green;
  marker.color.b = blue;
  marker.color.a = 1.0f;
  return marker;
}

/// The points a primitive is drawn through, from its start to its end: a segment's ends, an
/// arc's chords of at most kArcDrawingStep, a clothoid's polyline; a rotation's position.
std::vector<core::Point2> drawnPoints(const core::PathPrimitive& primitive) {
  switch (primitive.kind()) {
    case core::PrimitiveKind::kRotation:
      return {primitive.start()};
    case core::PrimitiveKind::kClothoid:
      return primitive.polyline(kClothoidDrawingTolerance);
    case core::PrimitiveKind::kArc: {
      const int steps =
          std::max(1, static_cast<int>(std::ceil(std::abs(primitive.sweep()) / kArcDrawingStep)));
      std::vector<core::Point2> points;
      for (int i = 0; i <= steps; ++i) {
        points.push_back(primitive.poseAt(static_cast<double>(i) / steps).position());
      }
      return points;
    }
    case core::PrimitiveKind::kSegment:
      break;
  }
  return {primitive.start(), primitive.end()};
}

/// The points a path is drawn through, each primitive's after the first's start.
std::vector<core::Point2> drawnPolyline(const std::vector<core::PathPrimitive>& path) {
  std::vector<core::Point2> points;
  if (!path.empty()) points.push_back(path.front().start());
  for (const core::PathPrimitive& primitive : path) {
    if (primitive.kind() == core::PrimitiveKind::kRotation) continue;
    const std::vector<core::Point2> drawn = drawnPoints(primitive);
    points.insert(points.end(), drawn.begin() + 1, drawn.end());
  }
  return points;
}

/// The points of `polyline` that the Douglas-Peucker simplification keeps within
/// `tolerance` metres of it: its ends and every point farther than that from the chord of
/// the points kept around it.
std::vector<core::Point2> simplifiedPolyline(const std::vector<core::Point2>& polyline,
                                             double tolerance) {
  if (polyline.size() <= 2) return polyline;
  std::vector<bool> kept(polyline.size(), false);
  kept.front() = kept.back() = true;
  std::vector<std::pair<std::size_t, std::size_t>> pieces{{0, polyline.size() - 1}};
  while (!pieces.empty()) {
    const auto [first, last] = pieces.back();
    pieces.pop_back();
    double farthest = tolerance;
    std::size_t split = first;
    for (std::size_t i = first + 1; i < last; ++i) {
      const double distance = core::distanceToSegment(polyline[i], polyline[first], polyline[last]);
      if (distance > farthest) {
        farthest = distance;
        split = i;
      }
    }
    if (split == first) continue;
    kept[split] = true;
    pieces.emplace_back(first, split);
    pieces.emplace_back(split, last);
  }
  std::vector<core::Point2> result;
  for (std::size_t i = 0; i < polyline.size(); ++i) {
    if (kept[i]) result.push_back(polyline[i]);
  }
  return result;
}

/// A path too long for MarkerScale::kPointBudget in its variants' colours: one grey strip
/// (namespace `trajectory`) simplified within the least tolerance, from a ten-thousandth of
/// the path's extent doubling, that keeps it and the rotations' spheres to the budget.
visualization_msgs::MarkerArray lakeScaleMarkers(const std::vector<core::PathPrimitive>& path,
                                                 const visualization_msgs::Marker& rotations,
                                                 const std_msgs::Header& header, double width,
                                                 double extent) {
  const std::vector<core::Point2> polyline = drawnPolyline(path);
  const std::size_t budget = MarkerScale::kPointBudget > rotations.points.size()
                                 ? MarkerScale::kPointBudget - rotations.points.size()
                                 : MarkerScale::kPointBudget / 2;
  std::vector<core::Point2> simplified = polyline;
  for (double tolerance = 1e-4 * extent; simplified.size() > budget; tolerance *= 2.0) {
    simplified = simplifiedPolyline(polyline, tolerance);
  }
  visualization_msgs::Marker strip = lineList("trajectory", header, 0.3f, 0.3f, 0.3f, width);
  strip.type = visualization_msgs::Marker::LINE_STRIP;
  for (const core::Point2& p : simplified) strip.points.push_back(point(p));
  visualization_msgs::MarkerArray markers;
  markers.markers.push_back(deleteAllMarker(header));
  markers.markers.push_back(strip);
  if (!rotations.points.empty() && rotations.points.size() <= MarkerScale::kPointBudget / 2) {
    markers.markers.push_back(rotations);
  }
  return markers;
}

/// A path's primitives' ends, whose extent sets its drawing scale.
core::Ring pathEnds(const std::vector<core::PathPrimitive>& path) {
  core::Ring ends;
  for (const core::PathPrimitive& primitive : path) ends.push_back(primitive.start());
  if (!path.empty()) ends.push_back(path.back().end());
  return ends;
}

}  // namespace

visualization_msgs::MarkerArray trajectoryMarkers(const std::vector<core::PathPrimitive>& path,
                                                  const std_msgs::Header& header) {
  const MarkerScale scale(pathEnds(path));
  const double width = scale.size(0.08);
  visualization_msgs::Marker segments = lineList("segments", header, 0.3f, 0.3f, 0.3f, width);
  visualization_msgs::Marker inner = lineList("arcs_inner", header, 0.1f, 0.7f, 0.2f, width);
  visualization_msgs::Marker bisector =
      lineList("arcs_outer_bisector", header, 0.1f, 0.3f, 0.9f, width);
  visualization_msgs::Marker tangent =
      lineList("arcs_outer_tangent", header, 0.8f, 0.1f, 0.8f, width);
  visualization_msgs::Marker reverse =
      lineList("arcs_reverse_curve", header, 0.1f, 0.7f, 0.7f, width);
  visualization_msgs::Marker bulb = lineList("arcs_bulb", header, 0.9f, 0.6f, 0.1f, width);
  visualization_msgs::Marker clothoids = lineList("clothoids", header, 0.2f, 0.7f, 0.2f, width);
  visualization_msgs::Marker rotations = lineList("rotations", header, 0.9f, 0.1f, 0.1f, width);
  rotations.type = visualization_msgs::Marker::SPHERE_LIST;
  rotations.scale.x = rotations.scale.y = rotations.scale.z = scale.size(0.3);
  for (const core::PathPrimitive& primitive : path) {
    const std::vector<core::Point2> drawn = drawnPoints(primitive);
    if (primitive.kind() == core::PrimitiveKind::kRotation) {
      rotations.points.push_back(point(drawn.front()));
      continue;
    }
    visualization_msgs::Marker& marker =
        primitive.kind() == core::PrimitiveKind::kSegment               ? segments
        : primitive.kind() == core::PrimitiveKind::kClothoid            ? clothoids
        : primitive.variant() == core::SmoothingVariant::kOuterBisector ? bisector
        : primitive.variant() == core::SmoothingVariant::kOuterTangent  ? tangent
        : primitive.variant() == core::SmoothingVariant::kReverseCurve  ? reverse
        : primitive.variant() == core::SmoothingVariant::kBulb          ? bulb
                                                                        : inner;
    for (std::size_t i = 1; i < drawn.size(); ++i) {
      marker.points.push_back(point(drawn[i - 1]));
      marker.points.push_back(point(drawn[i]));
    }
  }
  visualization_msgs::MarkerArray markers;
  markers.markers.push_back(deleteAllMarker(header));
  for (visualization_msgs::Marker* marker :
       {&segments, &inner, &bisector, &tangent, &reverse, &bulb, &clothoids, &rotations}) {
    if (!marker->points.empty()) markers.markers.push_back(*marker);
  }
  if (MarkerScale::pointCount(markers) <= MarkerScale::kPointBudget) return markers;
  return lakeScaleMarkers(path, rotations, header, width,
                          scale.size(MarkerScale::kReferenceExtent));
}

visualization_msgs::MarkerArray closestApproachMarkers(const core::Point2& where,
                                                       double clearance_m, double wall_distance,
                                                       const std_msgs::Header& header,
                                                       double size) {
  visualization_msgs::Marker sphere = lineList("closest_approach", header, 0.8f, 0.0f, 0.45f);
  sphere.type = visualization_msgs::Marker::SPHERE;
  sphere.pose.position = point(where);
  sphere.scale.x = sphere.scale.y = sphere.scale.z = size;
  sphere.color.a = 0.8f;
  visualization_msgs::Marker text = sphere;
  text.id = 1;
  text.type = visualization_msgs::Marker::TEXT_VIEW_FACING;
  text.pose.position.z += size;
  text.scale.x = text.scale.y = 0.0;
  text.color.a = 1.0f;
  std::ostringstream label;
  label.precision(3);
  label << clearance_m << " m from a wall (wall_distance " << wall_distance << " m)";
  text.text = label.str();
  visualization_msgs::MarkerArray markers;
  markers.markers = {sphere, text};
  return markers;
}

}  // namespace kinematic_coverage::nodes
