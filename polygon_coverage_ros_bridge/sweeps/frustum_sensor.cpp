#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"

#include <cmath>

namespace kinematic_coverage::core {

FrustumSensor::FrustumSensor(double width, double length, double lateral_overlap)
    : width_(width), length_(length), sweep_distance_((1.0 - lateral_overlap) * width) {}

FrustumSensor FrustumSensor::fromOptions(const SensorOptions& options) {
  if (options.model == SensorModel::kLine) {
    return FrustumSensor(options.lateral_footprint, 0.0, options.lateral_overlap);
  }
  const double d = options.sensor_distance;
  return FrustumSensor(2.0 * d * std::tan(0.5 * options.lateral_fov),
                       2.0 * d * std::tan(0.5 * options.onward_fov), options.lateral_overlap);
}

Ring FrustumSensor::footprint(const Pose2& pose) const {
  const Point2 along(std::cos(pose.yaw), std::sin(pose.yaw));
  const Point2 across(-along.y(), along.x());
  const Point2 centre = pose.position();
  const Point2 half_along = 0.5 * length_ * along;
  const Point2 half_across = 0.5 * width_ * across;
  return {centre - half_along - half_across, centre + half_along - half_across,
          centre + half_along + half_across, centre - half_along + half_across};
}

}  // namespace kinematic_coverage::core
