#pragma once

namespace kinematic_coverage::core {

/// Which sensor looks at the bottom (`sensor_model`).
enum class SensorModel {
  kFrustum,  ///< a camera or sonar frustum: a rectangle grown with the distance
  kLine,     ///< a line sensor of a fixed width, no length
};

/// The sensor options the sweeps stage reads (docs/REFERENCE.md, Sensor footprint and
/// coverage): what the footprint is and how much neighbouring lanes overlap.
struct SensorOptions {
  SensorModel model = SensorModel::kFrustum;
  double lateral_fov = 2.27;       ///< rad, frustum only
  double onward_fov = 0.52;        ///< rad, frustum only
  double lateral_footprint = 2.0;  ///< m, line only
  double sensor_distance = 3.0;    ///< m between sensor and bottom, frustum only
  double lateral_overlap = 0.4;    ///< fraction of the width in [0, 1)
};

}  // namespace kinematic_coverage::core
