#include "trajectory_generation_tools/trajectory/primitive_path_validation.h"

#include <cmath>
#include <string>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {
namespace {

bool isFinite(const Point2& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }

}  // namespace

bool isDegenerate(const PathPrimitive& primitive) {
  if (primitive.kind() == PrimitiveKind::kRotation) {
    return primitive.turnAngle() <= kDegenerateTurn;
  }
  return primitive.length() <= kDegenerateLength;
}

void validatePrimitivePath(const std::vector<PathPrimitive>& path) {
  for (std::size_t i = 0; i < path.size(); ++i) {
    const PathPrimitive& primitive = path[i];
    const std::string name = "path primitive " + std::to_string(i);
    if (!isFinite(primitive.start()) || !isFinite(primitive.end()) ||
        !std::isfinite(primitive.startAngle()) || !std::isfinite(primitive.sweep()) ||
        !std::isfinite(primitive.length())) {
      throw InvalidInputError(name + " has a non-finite coordinate or angle");
    }
    if (primitive.kind() == PrimitiveKind::kArc &&
        (!std::isfinite(primitive.radius()) || !(primitive.radius() > 0.0) ||
         !isFinite(primitive.centre()))) {
      throw InvalidInputError(name + " is an arc with radius " +
                              std::to_string(primitive.radius()) +
                              "; it must be positive and finite");
    }
    if (i > 0) {
      const double gap = (primitive.start() - path[i - 1].end()).norm();
      if (!(gap <= kJoinPositionTolerance)) {
        throw InvalidInputError(name + " starts " + std::to_string(gap) +
                                " m from the end of primitive " + std::to_string(i - 1) +
                                "; the path must be continuous");
      }
    }
  }
}

}  // namespace kinematic_coverage::core
