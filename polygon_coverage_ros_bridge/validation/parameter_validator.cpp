#include "polygon_coverage_ros_bridge/validation/parameter_validator.h"

#include <cmath>
#include <string>
#include <vector>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/validation/point_format.h"

namespace kinematic_coverage::core {
namespace {

void requirePositive(const char* name, double value, const char* unit) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw InvalidInputError(std::string(name) + " = " + formatNumber(value) +
                            " is out of range: it must be a finite number > 0 (" + unit + ")");
  }
}

void requireOpenAngle(const char* name, double value) {
  if (!(std::isfinite(value) && value > 0.0 && value < M_PI)) {
    throw InvalidInputError(std::string(name) + " = " + formatNumber(value) +
                            " is out of range: it must be in (0, pi) rad");
  }
}

void requireOneOf(const char* name, const std::string& value,
                  const std::vector<std::string>& allowed) {
  std::string list;
  for (const std::string& candidate : allowed) {
    if (value == candidate) return;
    list += (list.empty() ? "" : ", ") + candidate;
  }
  throw InvalidInputError(std::string(name) + " = '" + value + "' is not one of: " + list);
}

}  // namespace

void ParameterValidator::validate(const PlannerParameters& p) const {
  requireOneOf("decomposition_type", p.decomposition_type, {"boustrophedon", "trapezoidal"});
  requireOneOf("cost_function", p.cost_function, {"distance", "time", "waypoints"});
  requirePositive("v_max", p.v_max, "m/s");
  requirePositive("a_max", p.a_max, "m/s^2");
  requirePositive("yaw_rate_max", p.yaw_rate_max, "rad/s");
  if (!(std::isfinite(p.wall_distance) && p.wall_distance >= 0.0)) {
    throw InvalidInputError("wall_distance = " + formatNumber(p.wall_distance) +
                            " is out of range: it must be a finite number >= 0 (m)");
  }
  requireOneOf("sensor_model", p.sensor_model, {"frustum", "line"});
  requireOpenAngle("lateral_fov", p.lateral_fov);
  requireOpenAngle("onward_fov", p.onward_fov);
  requirePositive("lateral_footprint", p.lateral_footprint, "m");
  requirePositive("sensor_distance", p.sensor_distance, "m");
  if (!(std::isfinite(p.lateral_overlap) && p.lateral_overlap >= 0.0 && p.lateral_overlap < 1.0)) {
    throw InvalidInputError("lateral_overlap = " + formatNumber(p.lateral_overlap) +
                            " is out of range: it must be in [0, 1)");
  }
  requirePositive("turning_radius", p.turning_radius, "m");
  requirePositive("segment_sampling_distance", p.segment_sampling_distance, "m");
  requirePositive("arc_sampling_distance", p.arc_sampling_distance, "m");
  requirePositive("rotation_sampling_angle", p.rotation_sampling_angle, "rad");
  requireOneOf("replanning_method", p.replanning_method,
               {"convex_hull", "concave_hull", "footprint"});
  requirePositive("alpha", p.alpha, "m");
}

}  // namespace kinematic_coverage::core
