#include "trajectory_generation_tools/trajectory/trajectory_timing.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "polygon_coverage_ros_bridge/base/trapezoidal_velocity_profile.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "trajectory_generation_tools/trajectory/primitive_path_validation.h"

namespace kinematic_coverage::core {
namespace {

void checkRate(double value, const std::string& name) {
  if (!std::isfinite(value) || !(value > 0.0)) {
    throw InvalidInputError(name + " must be positive and finite, got " + std::to_string(value));
  }
}

/// Seconds to cover `distance` while the speed changes uniformly from `from` to `to`.
double uniformChangeTime(double distance, double from, double to) {
  return distance > 0.0 ? 2.0 * distance / (from + to) : 0.0;
}

}  // namespace

TrajectoryTiming::TrajectoryTiming(const VehicleLimits& limits) : limits_(limits) {
  checkRate(limits.v_max, "the speed limit");
  checkRate(limits.a_max, "the acceleration limit");
  checkRate(limits.yaw_rate_max, "the yaw rate limit");
}

TrajectoryTiming::TrajectoryTiming(double v_max, double a_max, double yaw_rate_max)
    : TrajectoryTiming(VehicleLimits{v_max, a_max, yaw_rate_max}) {}

std::vector<PrimitiveTiming> TrajectoryTiming::profile(
    const std::vector<PathPrimitive>& path) const {
  validatePrimitivePath(path);
  std::vector<PrimitiveTiming> timings(path.size());

  // The primitives that move (segments and arcs that are not degenerate), and the speed
  // limit at the joint before each of them and after the last: 0 where the robot stops.
  std::vector<std::size_t> moving;
  std::vector<double> joint_limit;
  bool stop_pending = true;
  for (std::size_t i = 0; i < path.size(); ++i) {
    const PathPrimitive& primitive = path[i];
    if (isDegenerate(primitive)) continue;
    if (primitive.kind() == PrimitiveKind::kRotation) {
      stop_pending = true;
      continue;
    }
    PrimitiveTiming& timing = timings[i];
    // A clothoid is driven no faster than an arc of its tightest radius.
    timing.speed_limit =
        primitive.kind() == PrimitiveKind::kArc || primitive.kind() == PrimitiveKind::kClothoid
            ? limits_.arcSpeed(primitive.radius())
            : limits_.v_max;
    double limit = 0.0;
    if (!stop_pending && !moving.empty()) {
      const PathPrimitive& previous = path[moving.back()];
      const double heading_jump =
          std::abs(wrapAngle(primitive.startPose().yaw - previous.endPose().yaw));
      if (heading_jump <= kJoinHeadingTolerance) {
        limit = std::min(timings[moving.back()].speed_limit, timing.speed_limit);
      }
    }
    joint_limit.push_back(limit);
    moving.push_back(i);
    stop_pending = false;
  }
  joint_limit.push_back(0.0);

  // Forward pass (accelerate at a_max), then backward pass (brake at a_max), on the joint
  // speeds; v^2 grows by at most 2 a_max L over a primitive of length L.
  const TrapezoidalVelocityProfile velocity(limits_);
  std::vector<double> speed(joint_limit.size(), 0.0);
  for (std::size_t k = 0; k < moving.size(); ++k) {
    const double reachable = velocity.reachableSpeed(speed[k], path[moving[k]].length());
    speed[k + 1] = std::min(joint_limit[k + 1], reachable);
  }
  for (std::size_t k = moving.size(); k-- > 0;) {
    const double reachable = velocity.reachableSpeed(speed[k + 1], path[moving[k]].length());
    speed[k] = std::min(speed[k], reachable);
  }
  for (std::size_t k = 0; k < moving.size(); ++k) {
    PrimitiveTiming& timing = timings[moving[k]];
    const double length = path[moving[k]].length();
    timing.entry_speed = speed[k];
    timing.exit_speed = speed[k + 1];
    timing.peak_speed =
        std::max({velocity.peakSpeed(speed[k], speed[k + 1], length, timing.speed_limit),
                  timing.entry_speed, timing.exit_speed});
  }

  double clock = 0.0;
  for (std::size_t i = 0; i < path.size(); ++i) {
    timings[i].start_time_s = clock;
    timings[i].duration_s = phasesOf(path[i], timings[i]).timeAt(1.0);
    clock += timings[i].duration_s;
  }
  return timings;
}

double TrajectoryTiming::timeWithin(const PathPrimitive& primitive, const PrimitiveTiming& timing,
                                    double fraction) const {
  return phasesOf(primitive, timing).timeAt(fraction);
}

TrajectoryTiming::Phases TrajectoryTiming::phasesOf(const PathPrimitive& primitive,
                                                    const PrimitiveTiming& timing) const {
  Phases phases;
  phases.velocity = TrapezoidalVelocityProfile(limits_);
  if (isDegenerate(primitive)) return phases;
  if (primitive.kind() == PrimitiveKind::kRotation) {
    phases.turn_duration = primitive.turnAngle() / limits_.yaw_rate_max;
    return phases;
  }
  phases.length = primitive.length();
  phases.entry = timing.entry_speed;
  phases.exit = timing.exit_speed;
  phases.peak = timing.peak_speed;
  phases.s1 =
      std::clamp(phases.velocity.changeDistance(phases.entry, phases.peak), 0.0, phases.length);
  phases.s2 = std::clamp(phases.length - phases.velocity.changeDistance(phases.exit, phases.peak),
                         phases.s1, phases.length);
  phases.t1 = uniformChangeTime(phases.s1, phases.entry, phases.peak);
  phases.t2 = phases.t1 + (phases.s2 - phases.s1) / phases.peak;
  return phases;
}

double TrajectoryTiming::Phases::timeAt(double fraction) const {
  const double f = std::clamp(fraction, 0.0, 1.0);
  if (!(length > 0.0)) return f * turn_duration;
  const double s = f * length;
  if (s <= s1) {
    const double speed = std::min(peak, velocity.reachableSpeed(entry, s));
    return uniformChangeTime(s, entry, speed);
  }
  if (s <= s2) return t1 + (s - s1) / peak;
  const double speed = std::min(peak, velocity.reachableSpeed(exit, length - s));
  return t2 + uniformChangeTime(s - s2, peak, speed);
}

double TrajectoryTiming::traversalTime(const std::vector<PathPrimitive>& path) const {
  const std::vector<PrimitiveTiming> timings = profile(path);
  return timings.empty() ? 0.0 : timings.back().start_time_s + timings.back().duration_s;
}

double TrajectoryTiming::assignTimes(const std::vector<PathPrimitive>& path,
                                     std::vector<TrajectoryPose>& poses) const {
  const std::vector<PrimitiveTiming> timings = profile(path);
  double previous = 0.0;
  std::size_t phases_of = path.size();
  Phases phases;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    TrajectoryPose& pose = poses[i];
    if (pose.primitive >= path.size()) {
      throw InvalidInputError("trajectory pose " + std::to_string(i) + " names primitive " +
                              std::to_string(pose.primitive) + " of a path of " +
                              std::to_string(path.size()));
    }
    if (pose.primitive != phases_of) {
      phases_of = pose.primitive;
      phases = phasesOf(path[phases_of], timings[phases_of]);
    }
    // Rounding must not let time run backwards across phase boundaries.
    pose.t = std::max(previous, timings[phases_of].start_time_s + phases.timeAt(pose.fraction));
    previous = pose.t;
  }
  return timings.empty() ? 0.0 : timings.back().start_time_s + timings.back().duration_s;
}

}  // namespace kinematic_coverage::core
