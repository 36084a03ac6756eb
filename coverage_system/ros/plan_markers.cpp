#include "coverage_system/ros/plan_markers.h"

#include <geometry_msgs/Point.h>

#include <algorithm>

#include "coverage_system/ros/marker_scale.h"
#include "coverage_system/ros/message_conversion.h"
#include "polygon_coverage_ros_bridge/geometry/boundary_simplification.h"

namespace kinematic_coverage::nodes {
namespace {

geometry_msgs::Point point(const core::Point2& p, double z = 0.0) {
  geometry_msgs::Point message;
  message.x = p.x();
  message.y = p.y();
  message.z = z;
  return message;
}

visualization_msgs::Marker baseMarker(const std::string& ns, int id, int type,
                                      const std_msgs::Header& header, float red, float green,
                                      float blue, double scale) {
  visualization_msgs::Marker marker;
  marker.header = header;
  marker.ns = ns;
  marker.id = id;
  marker.type = type;
  marker.action = visualization_msgs::Marker::ADD;
  marker.pose.orientation.w = 1.0;
  marker.scale.x = scale;
  marker.scale.y = scale;
  marker.scale.z = scale;
  marker.color.r = red;
  marker.color.g = green;
  marker.color.b = blue;
  marker.color.a = 1.0f;
  return marker;
}

/// The hull (dark) and holes (grey) of the polygon, namespace `polygon`, lines `width` wide
/// through every `stride`-th vertex.
void appendPolygon(const core::PolygonWithHoles& polygon, const std_msgs::Header& header,
                   double width, std::size_t stride, visualization_msgs::MarkerArray* markers) {
  markers->markers.push_back(
      ringMarker(polygon.hull, "polygon", 0, header, 0.1f, 0.1f, 0.1f, width, stride));
  int id = 1;
  for (const core::Ring& hole : polygon.holes) {
    markers->markers.push_back(
        ringMarker(hole, "polygon", id++, header, 0.4f, 0.4f, 0.4f, width, stride));
  }
}

visualization_msgs::Marker startMarker(const core::Point2& start, const std_msgs::Header& header,
                                       double size = 0.6) {
  visualization_msgs::Marker marker = baseMarker(
      "start_goal", 0, visualization_msgs::Marker::SPHERE, header, 0.1f, 0.7f, 0.2f, size);
  marker.pose.position = point(start);
  return marker;
}

visualization_msgs::Marker goalMarker(const core::Point2& goal, const std_msgs::Header& header,
                                      double size = 0.6) {
  visualization_msgs::Marker marker =
      baseMarker("start_goal", 1, visualization_msgs::Marker::CUBE, header, 0.5f, 0.2f, 0.6f, size);
  marker.pose.position = point(goal);
  return marker;
}

}  // namespace

visualization_msgs::Marker ringMarker(const core::Ring& ring, const std::string& ns, int id,
                                      const std_msgs::Header& header, float red, float green,
                                      float blue, double width, std::size_t stride) {
  visualization_msgs::Marker marker =
      baseMarker(ns, id, visualization_msgs::Marker::LINE_STRIP, header, red, green, blue, width);
  for (std::size_t i = 0; i < ring.size(); i += std::max<std::size_t>(1, stride)) {
    marker.points.push_back(point(ring[i]));
  }
  if (!ring.empty()) marker.points.push_back(point(ring.front()));
  return marker;
}

visualization_msgs::Marker deleteAllMarker(const std_msgs::Header& header) {
  visualization_msgs::Marker marker;
  marker.header = header;
  marker.action = visualization_msgs::Marker::DELETEALL;
  return marker;
}

namespace {

/// A marker colour.
struct MarkerColour {
  float red = 0.0f;
  float green = 0.0f;
  float blue = 0.0f;
};

/// The hulls and holes of `parts` as line strips of namespace `ns`, numbered from 0,
/// through every `stride`-th vertex.
void appendParts(const std::vector<core::PolygonWithHoles>& parts, const std::string& ns,
                 const std_msgs::Header& header, const MarkerColour& colour, double width,
                 std::size_t stride, visualization_msgs::MarkerArray* markers) {
  int id = 0;
  for (const core::PolygonWithHoles& part : parts) {
    markers->markers.push_back(ringMarker(part.hull, ns, id++, header, colour.red, colour.green,
                                          colour.blue, width, stride));
    for (const core::Ring& hole : part.holes) {
      markers->markers.push_back(
          ringMarker(hole, ns, id++, header, colour.red, colour.green, colour.blue, width, stride));
    }
  }
}

/// Every how many vertices the plan's rings (free area, offset parts, unreachable parts,
/// cells) are drawn, so that with `other_points` they keep to MarkerScale::kPointBudget
/// (at least kMinRingPoints for the rings).
std::size_t ringStride(const core::PolygonWithHoles& free_area, const core::CoveragePlan& plan,
                       std::size_t other_points) {
  constexpr std::size_t kMinRingPoints = 2000;
  std::size_t rings = core::BoundarySimplification::vertexCount(free_area);
  for (const auto* parts : {&plan.offset_parts, &plan.unreachable_parts}) {
    for (const core::PolygonWithHoles& part : *parts)
      rings += core::BoundarySimplification::vertexCount(part);
  }
  for (const core::Ring& cell : plan.cells) rings += cell.size();
  const std::size_t budget = other_points + kMinRingPoints >= MarkerScale::kPointBudget
                                 ? kMinRingPoints
                                 : MarkerScale::kPointBudget - other_points;
  return MarkerScale::stride(rings, budget);
}

}  // namespace

visualization_msgs::MarkerArray planMarkers(const core::PolygonWithHoles& free_area,
                                            const core::CoveragePlan& plan,
                                            const core::Point2& start, const core::Point2& goal,
                                            const std_msgs::Header& header) {
  const MarkerScale scale(free_area.hull);
  // Waypoint spheres at most a quarter of the budget; the path through every waypoint.
  const std::size_t sphere_stride =
      MarkerScale::stride(plan.waypoints.size(), MarkerScale::kPointBudget / 4);
  std::size_t gap_points = 0;
  for (const core::OffsetGap& gap : plan.gaps) gap_points += gap.path.size();
  const std::size_t stride =
      ringStride(free_area, plan,
                 plan.waypoints.size() + plan.waypoints.size() / sphere_stride + gap_points + 2);
  visualization_msgs::MarkerArray markers;
  markers.markers.push_back(deleteAllMarker(header));
  appendPolygon(free_area, header, scale.size(0.1), stride, &markers);
  appendParts(plan.offset_parts, "offset_free_area", header, {0.6f, 0.6f, 0.6f}, scale.size(0.04),
              stride, &markers);
  appendParts(plan.unreachable_parts, "unreachable_parts", header, {0.8f, 0.0f, 0.45f},
              scale.size(0.06), stride, &markers);
  int id = 0;
  for (const core::OffsetGap& gap : plan.gaps) {
    visualization_msgs::Marker line =
        baseMarker("gaps", id++, visualization_msgs::Marker::LINE_STRIP, header, 1.0f, 0.2f, 0.6f,
                   scale.size(0.1));
    for (const core::Point2& p : gap.path) line.points.push_back(point(p));
    markers.markers.push_back(line);
  }
  id = 0;
  for (const core::Ring& cell : plan.cells) {
    markers.markers.push_back(
        ringMarker(cell, "cells", id++, header, 0.2f, 0.5f, 0.9f, scale.size(0.05), stride));
  }
  visualization_msgs::Marker path =
      baseMarker("waypoint_path", 0, visualization_msgs::Marker::LINE_STRIP, header, 0.95f, 0.45f,
                 0.1f, scale.size(0.08));
  visualization_msgs::Marker waypoints =
      baseMarker("waypoints", 0, visualization_msgs::Marker::SPHERE_LIST, header, 0.95f, 0.45f,
                 0.1f, scale.size(0.25));
  for (std::size_t i = 0; i < plan.waypoints.size(); ++i) {
    path.points.push_back(point(plan.waypoints[i].position(), 0.01));
    if (i % sphere_stride == 0)
      waypoints.points.push_back(point(plan.waypoints[i].position(), 0.01));
  }
  markers.markers.push_back(path);
  markers.markers.push_back(waypoints);
  markers.markers.push_back(startMarker(start, header, scale.size(0.6)));
  markers.markers.push_back(goalMarker(goal, header, scale.size(0.6)));
  return markers;
}

visualization_msgs::MarkerArray inputMarkers(
    const kinematic_coverage::PolygonWithHolesStamped* polygon,
    const geometry_msgs::PointStamped* start, const geometry_msgs::PointStamped* goal) {
  visualization_msgs::MarkerArray markers;
  const std_msgs::Header& any = polygon != nullptr ? polygon->header
                                : start != nullptr ? start->header
                                                   : goal->header;
  markers.markers.push_back(deleteAllMarker(any));
  // Non-finite input is drawn in no part (rviz refuses such markers); the planner names it.
  const auto finite = [](const core::Point2& p) { return p.allFinite(); };
  if (polygon != nullptr) {
    const core::PolygonWithHoles rings = fromMessage(polygon->polygon);
    bool drawable = std::all_of(rings.hull.begin(), rings.hull.end(), finite);
    for (const core::Ring& hole : rings.holes) {
      drawable = drawable && std::all_of(hole.begin(), hole.end(), finite);
    }
    const std::size_t stride = MarkerScale::stride(core::BoundarySimplification::vertexCount(rings),
                                                   MarkerScale::kPointBudget);
    if (drawable) {
      appendPolygon(rings, polygon->header, MarkerScale(rings.hull).size(0.1), stride, &markers);
    }
  }
  const auto position = [](const geometry_msgs::PointStamped& p) {
    return core::Point2(p.point.x, p.point.y);
  };
  if (start != nullptr && finite(position(*start))) {
    markers.markers.push_back(startMarker(position(*start), start->header));
  }
  if (goal != nullptr && finite(position(*goal))) {
    markers.markers.push_back(goalMarker(position(*goal), goal->header));
  }
  return markers;
}

}  // namespace kinematic_coverage::nodes
