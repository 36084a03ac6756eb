#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"

#include <cmath>

namespace kinematic_coverage::core {

FrustumSensor::FrustumSensor(double width, double length, double lateral_overlap)
    : width_(width), length_(length), sweep_distance_((1.0 - lateral_overlap) * width) {}

FrustumSensor FrustumSensor::fromParameters(const PlannerParameters& parameters) {
  if (parameters.sensor_model == "line") {
    return FrustumSensor(parameters.lateral_footprint, 0.0, parameters.lateral_overlap);
  }
  const double d = parameters.sensor_distance;
  return FrustumSensor(2.0 * d * std::tan(0.5 * parameters.lateral_fov),
                       2.0 * d * std::tan(0.5 * parameters.onward_fov), parameters.lateral_overlap);
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
