#pragma once

#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"
#include "polygon_coverage_ros_bridge/sweeps/sensor_options.h"

namespace kinematic_coverage::core {

/// The sensor's footprint on the bottom (docs/REFERENCE.md, Sensor footprint and coverage):
/// a rectangle centred on the pose, `width` across the heading and `length` along it. At
/// distance d a frustum sensor sees W = 2 d tan(lateral_fov / 2), L = 2 d tan(onward_fov / 2);
/// a line sensor sees W = lateral_footprint, L = 0.
class FrustumSensor {
 public:
  FrustumSensor(double width, double length, double lateral_overlap);

  /// The sensor that the options describe (frustum or line).
  static FrustumSensor fromOptions(const SensorOptions& options);

  double width() const { return width_; }
  double length() const { return length_; }
  /// Distance between neighbouring sweep lanes: (1 - lateral_overlap) * W.
  double sweepDistance() const { return sweep_distance_; }

  /// The footprint's four corners (counter-clockwise) at a pose.
  Ring footprint(const Pose2& pose) const;

 private:
  double width_;
  double length_;
  double sweep_distance_;
};

}  // namespace kinematic_coverage::core
