#include "trajectory_generation_tools/trajectory/trajectory_sampler.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "trajectory_generation_tools/trajectory/primitive_path_validation.h"

namespace kinematic_coverage::core {
namespace {

/// Arc poses are recomputed from the angle this often (see appendPoses).
constexpr std::size_t kArcResyncSteps = 64;

double checkedInterval(double value, const std::string& name) {
  if (!std::isfinite(value) || !(value > 0.0)) {
    throw InvalidInputError(name + " must be positive and finite, got " + std::to_string(value));
  }
  return value;
}

/// wrapAngle for angles at most one turn out of (-pi, pi], without its division.
double wrapNear(double angle) {
  if (angle > M_PI) angle -= 2.0 * M_PI;
  if (angle <= -M_PI) angle += 2.0 * M_PI;
  return angle > -M_PI && angle <= M_PI ? angle : wrapAngle(angle);
}

}  // namespace

TrajectorySampler::TrajectorySampler(double segment_sampling_distance, double arc_sampling_distance,
                                     double rotation_sampling_angle)
    : segment_sampling_distance_(
          checkedInterval(segment_sampling_distance, "the sampling distance along segments")),
      arc_sampling_distance_(
          checkedInterval(arc_sampling_distance, "the sampling distance along arcs")),
      rotation_sampling_angle_(
          checkedInterval(rotation_sampling_angle, "the sampling angle of rotations")) {}

std::size_t TrajectorySampler::pieces(const PathPrimitive& primitive) const {
  double ratio = 0.0;
  switch (primitive.kind()) {
    case PrimitiveKind::kSegment:
      ratio = primitive.length() / segment_sampling_distance_;
      break;
    case PrimitiveKind::kArc:
    case PrimitiveKind::kClothoid:
      ratio = primitive.length() / arc_sampling_distance_;
      break;
    case PrimitiveKind::kRotation:
      ratio = primitive.turnAngle() / rotation_sampling_angle_;
      break;
  }
  if (!(ratio < static_cast<double>(kMaxPoses))) {
    throw SizeLimitError("sampling a primitive of the path would need more than " +
                         std::to_string(kMaxPoses) + " poses");
  }
  return std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(ratio)));
}

void TrajectorySampler::appendPoses(const PathPrimitive& primitive, std::size_t index,
                                    std::size_t first, std::size_t count,
                                    std::vector<TrajectoryPose>& poses) {
  TrajectoryPose pose;
  pose.kind = primitive.kind();
  pose.primitive = static_cast<std::uint32_t>(index);
  // The heading at the start, then per fraction of the primitive.
  const double start_yaw = primitive.startPose().yaw;
  const double yaw_change = primitive.kind() == PrimitiveKind::kSegment ? 0.0 : primitive.sweep();
  pose.x = primitive.start().x();
  pose.y = primitive.start().y();
  pose.yaw = start_yaw;
  if (first == 0) poses.push_back(pose);
  // Interior poses, by kind so each loop stays branch-free.
  const double step = 1.0 / static_cast<double>(count);
  switch (primitive.kind()) {
    case PrimitiveKind::kSegment: {
      const Point2 delta = primitive.end() - primitive.start();
      pose.yaw = start_yaw;
      for (std::size_t k = 1; k < count; ++k) {
        pose.fraction = static_cast<double>(k) * step;
        pose.x = primitive.start().x() + pose.fraction * delta.x();
        pose.y = primitive.start().y() + pose.fraction * delta.y();
        poses.push_back(pose);
      }
      break;
    }
    case PrimitiveKind::kArc: {
      // The radius vector turns by a fixed angle per pose: one rotation per step instead
      // of a cosine and a sine, recomputed exactly every kArcResyncSteps steps so that
      // rounding cannot accumulate.
      const double step_angle = step * primitive.sweep();
      const double c = std::cos(step_angle);
      const double s = std::sin(step_angle);
      Point2 radius_vector = primitive.start() - primitive.centre();
      for (std::size_t k = 1; k < count; ++k) {
        pose.fraction = static_cast<double>(k) * step;
        if (k % kArcResyncSteps == 0) {
          const double angle = primitive.startAngle() + pose.fraction * primitive.sweep();
          radius_vector = primitive.radius() * Point2(std::cos(angle), std::sin(angle));
        } else {
          radius_vector = Point2(c * radius_vector.x() - s * radius_vector.y(),
                                 s * radius_vector.x() + c * radius_vector.y());
        }
        pose.x = primitive.centre().x() + radius_vector.x();
        pose.y = primitive.centre().y() + radius_vector.y();
        pose.yaw = wrapNear(start_yaw + pose.fraction * yaw_change);
        poses.push_back(pose);
      }
      break;
    }
    case PrimitiveKind::kRotation:
      for (std::size_t k = 1; k < count; ++k) {
        pose.fraction = static_cast<double>(k) * step;
        pose.yaw = wrapNear(start_yaw + pose.fraction * yaw_change);
        poses.push_back(pose);
      }
      break;
    case PrimitiveKind::kClothoid:
      for (std::size_t k = 1; k < count; ++k) {
        pose.fraction = static_cast<double>(k) * step;
        const Pose2 at = primitive.poseAt(pose.fraction);
        const double s = pose.fraction * primitive.length();
        pose.x = at.x;
        pose.y = at.y;
        pose.yaw = wrapNear(start_yaw + primitive.startCurvature() * s +
                            0.5 * primitive.curvatureRate() * s * s);
        poses.push_back(pose);
      }
      break;
  }
  pose.x = primitive.end().x();
  pose.y = primitive.end().y();
  pose.yaw = wrapNear(start_yaw + yaw_change);
  pose.fraction = 1.0;
  poses.push_back(pose);
}

std::vector<TrajectoryPose> TrajectorySampler::sample(
    const std::vector<PathPrimitive>& path) const {
  std::vector<TrajectoryPose> poses;
  sample(path, poses);
  return poses;
}

void TrajectorySampler::sample(const std::vector<PathPrimitive>& path,
                               std::vector<TrajectoryPose>& poses) const {
  validatePrimitivePath(path);
  poses.clear();
  if (path.empty()) return;
  if (path.size() > std::numeric_limits<std::uint32_t>::max()) {
    throw InvalidInputError("a path of " + std::to_string(path.size()) +
                            " primitives is too long to sample");
  }

  std::vector<std::size_t> piece_counts(path.size(), 0);
  std::size_t total = 1;
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (isDegenerate(path[i])) continue;
    piece_counts[i] = pieces(path[i]);
    total += piece_counts[i] + 1;
    if (total > kMaxPoses) {
      throw SizeLimitError("sampling the path would need more than " + std::to_string(kMaxPoses) +
                           " poses");
    }
  }
  poses.reserve(total);

  for (std::size_t i = 0; i < path.size(); ++i) {
    if (piece_counts[i] == 0) continue;
    const PathPrimitive& primitive = path[i];
    // A joint shared with the previous pose appears once; a heading jump keeps both.
    const bool joins =
        !poses.empty() &&
        std::abs(wrapAngle(primitive.startPose().yaw - poses.back().yaw)) <= kJoinHeadingTolerance;
    appendPoses(primitive, i, joins ? 1 : 0, piece_counts[i], poses);
  }
  if (poses.empty()) {
    TrajectoryPose only;
    only.x = path.front().start().x();
    only.y = path.front().start().y();
    only.yaw = path.front().startPose().yaw;
    only.kind = path.front().kind();
    poses.push_back(only);
  }
}

}  // namespace kinematic_coverage::core
