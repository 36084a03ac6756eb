#include "polygon_coverage_ros_bridge/route/segment_cost.h"

#include <cmath>
#include <sstream>
#include <utility>

#include "polygon_coverage_ros_bridge/base/trapezoidal_velocity_profile.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {

SegmentCost::SegmentCost(CostFunction cost_function, const VehicleLimits& limits)
    : cost_function_(cost_function), limits_(limits) {
  if (cost_function_ != CostFunction::kTime) return;
  for (const auto& [name, value] : {std::pair<const char*, double>{"speed", limits.v_max},
                                    std::pair<const char*, double>{"acceleration", limits.a_max}}) {
    if (!std::isfinite(value) || value <= 0.0) {
      std::ostringstream message;
      message << "SegmentCost: the " << name << " limit must be a positive number for the time "
              << "cost, got " << value;
      throw InvalidInputError(message.str());
    }
  }
}

double SegmentCost::ofLength(double length) const {
  if (!std::isfinite(length) || length < 0.0) {
    std::ostringstream message;
    message << "segment length must be a finite number >= 0, got " << length;
    throw InvalidInputError(message.str());
  }
  switch (cost_function_) {
    case CostFunction::kDistance:
      return length;
    case CostFunction::kTime:
      return TrapezoidalVelocityProfile(limits_).restToRestTime(length);
    case CostFunction::kWaypoints:
      return length <= kLengthTolerance ? 0.0 : 1.0;
  }
  return length;
}

double SegmentCost::of(const Point2& a, const Point2& b) const { return ofLength((b - a).norm()); }

double SegmentCost::pathCost(const std::vector<Point2>& path) const {
  double total = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) total += of(path[i - 1], path[i]);
  return total;
}

double pathLength(const std::vector<Point2>& path) {
  double total = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) total += (path[i] - path[i - 1]).norm();
  return total;
}

}  // namespace kinematic_coverage::core
