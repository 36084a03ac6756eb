#include "coverage_system/ros/trajectory_markers.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "coverage_system/ros/plan_markers.h"

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
                                    float red, float green, float blue) {
  visualization_msgs::Marker marker;
  marker.header = header;
  marker.ns = ns;
  marker.id = 0;
  marker.type = visualization_msgs::Marker::LINE_LIST;
  marker.action = visualization_msgs::Marker::ADD;
  marker.pose.orientation.w = 1.0;
  marker.scale.x = 0.08;
  marker.color.r = red;
  marker.color.g = green;
  marker.color.b = blue;
  marker.color.a = 1.0f;
  return marker;
}

/// m: the closest approach's sphere and the height of its text.
constexpr double kClosestApproachMarkerSize = 0.6;

}  // namespace

visualization_msgs::MarkerArray trajectoryMarkers(const std::vector<core::PathPrimitive>& path,
                                                  const std_msgs::Header& header) {
  visualization_msgs::Marker segments = lineList("segments", header, 0.3f, 0.3f, 0.3f);
  visualization_msgs::Marker inner = lineList("arcs_inner", header, 0.1f, 0.7f, 0.2f);
  visualization_msgs::Marker bisector = lineList("arcs_outer_bisector", header, 0.1f, 0.3f, 0.9f);
  visualization_msgs::Marker tangent = lineList("arcs_outer_tangent", header, 0.8f, 0.1f, 0.8f);
  visualization_msgs::Marker reverse = lineList("arcs_reverse_curve", header, 0.1f, 0.7f, 0.7f);
  visualization_msgs::Marker bulb = lineList("arcs_bulb", header, 0.9f, 0.6f, 0.1f);
  visualization_msgs::Marker clothoids = lineList("clothoids", header, 0.2f, 0.7f, 0.2f);
  visualization_msgs::Marker rotations = lineList("rotations", header, 0.9f, 0.1f, 0.1f);
  rotations.type = visualization_msgs::Marker::SPHERE_LIST;
  rotations.scale.x = rotations.scale.y = rotations.scale.z = 0.3;
  for (const core::PathPrimitive& primitive : path) {
    switch (primitive.kind()) {
      case core::PrimitiveKind::kSegment:
        segments.points.push_back(point(primitive.start()));
        segments.points.push_back(point(primitive.end()));
        break;
      case core::PrimitiveKind::kRotation:
        rotations.points.push_back(point(primitive.start()));
        break;
      case core::PrimitiveKind::kClothoid: {
        const std::vector<core::Point2> chords = primitive.polyline(kClothoidDrawingTolerance);
        for (std::size_t i = 1; i < chords.size(); ++i) {
          clothoids.points.push_back(point(chords[i - 1]));
          clothoids.points.push_back(point(chords[i]));
        }
        break;
      }
      case core::PrimitiveKind::kArc: {
        visualization_msgs::Marker& marker =
            primitive.variant() == core::SmoothingVariant::kOuterBisector  ? bisector
            : primitive.variant() == core::SmoothingVariant::kOuterTangent ? tangent
            : primitive.variant() == core::SmoothingVariant::kReverseCurve ? reverse
            : primitive.variant() == core::SmoothingVariant::kBulb         ? bulb
                                                                           : inner;
        const int steps =
            std::max(1, static_cast<int>(std::ceil(std::abs(primitive.sweep()) / kArcDrawingStep)));
        for (int i = 0; i < steps; ++i) {
          marker.points.push_back(
              point(primitive.poseAt(static_cast<double>(i) / steps).position()));
          marker.points.push_back(
              point(primitive.poseAt(static_cast<double>(i + 1) / steps).position()));
        }
        break;
      }
    }
  }
  visualization_msgs::MarkerArray markers;
  markers.markers.push_back(deleteAllMarker(header));
  for (visualization_msgs::Marker* marker :
       {&segments, &inner, &bisector, &tangent, &reverse, &bulb, &clothoids, &rotations}) {
    if (!marker->points.empty()) markers.markers.push_back(*marker);
  }
  return markers;
}

visualization_msgs::MarkerArray closestApproachMarkers(const core::Point2& where,
                                                       double clearance_m, double wall_distance,
                                                       const std_msgs::Header& header) {
  visualization_msgs::Marker sphere = lineList("closest_approach", header, 0.8f, 0.0f, 0.45f);
  sphere.type = visualization_msgs::Marker::SPHERE;
  sphere.pose.position = point(where);
  sphere.scale.x = sphere.scale.y = sphere.scale.z = kClosestApproachMarkerSize;
  sphere.color.a = 0.8f;
  visualization_msgs::Marker text = sphere;
  text.id = 1;
  text.type = visualization_msgs::Marker::TEXT_VIEW_FACING;
  text.pose.position.z += kClosestApproachMarkerSize;
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
