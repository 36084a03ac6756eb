#pragma once

#include <string>

namespace kinematic_coverage::core {

/// Every parameter of INTERFACE section 5, with its default. The same names are the keys
/// of mission files, `--set name=value`, config/default.yaml and the nodes' private
/// parameters. Units: metres, radians, seconds.
struct PlannerParameters {
  std::string decomposition_type = "boustrophedon";  ///< or "trapezoidal"
  std::string cost_function = "time";                ///< "distance", "time" or "waypoints"
  double v_max = 0.5;                                ///< m/s
  double a_max = 0.2;                                ///< m/s^2
  double yaw_rate_max = 0.5;                         ///< rad/s
  double wall_distance = 1.0;                        ///< m kept from hull and holes
  std::string sensor_model = "frustum";              ///< or "line"
  double lateral_fov = 2.27;                         ///< rad
  double onward_fov = 0.52;                          ///< rad
  double lateral_footprint = 2.0;                    ///< m, line sensor only
  double sensor_distance = 3.0;                      ///< m between sensor and bottom
  double lateral_overlap = 0.4;                      ///< fraction in [0, 1)
  bool smoothing = true;                             ///< false: segments and rotations
  double turning_radius = 1.0;                       ///< m
  double segment_sampling_distance = 0.5;            ///< m
  double arc_sampling_distance = 0.1;                ///< m
  double rotation_sampling_angle = 0.2;              ///< rad
  std::string replanning_method = "footprint";       ///< "convex_hull", "concave_hull", "footprint"
  double alpha = 2.0;                                ///< m, alpha-shape parameter
};

}  // namespace kinematic_coverage::core
