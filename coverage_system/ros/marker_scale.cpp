#include "coverage_system/ros/marker_scale.h"

#include <algorithm>

namespace kinematic_coverage::nodes {

MarkerScale::MarkerScale(const core::Ring& outline) {
  if (outline.empty()) return;
  core::Point2 low = outline.front();
  core::Point2 high = low;
  for (const core::Point2& p : outline) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  const double extent = (high - low).maxCoeff();
  if (std::isfinite(extent)) factor_ = std::max(1.0, extent / kReferenceExtent);
}

std::size_t MarkerScale::stride(std::size_t ring_points, std::size_t budget) {
  if (budget == 0) return std::max<std::size_t>(1, ring_points);
  return std::max<std::size_t>(1, (ring_points + budget - 1) / budget);
}

std::size_t MarkerScale::pointCount(const visualization_msgs::MarkerArray& markers) {
  std::size_t count = 0;
  for (const visualization_msgs::Marker& marker : markers.markers) {
    if (marker.action != visualization_msgs::Marker::ADD) continue;
    count += marker.points.empty() ? 1 : marker.points.size();
  }
  return count;
}

}  // namespace kinematic_coverage::nodes
