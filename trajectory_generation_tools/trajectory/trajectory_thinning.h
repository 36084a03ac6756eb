#pragma once

#include <vector>

#include "trajectory_generation_tools/trajectory/trajectory_pose.h"

namespace kinematic_coverage::core {

/// Thins a sampled trajectory for the files written of it (`trajectory_output_spacing`):
/// a lake's trajectory sampled every few metres has hundreds of thousands of poses, most of
/// them on straight legs, where two poses say all. It keeps every primitive's end poses (so
/// that straight pieces stay exact), every pose of a rotation, and between those one pose
/// per `spacing` metres of travel, or wherever the heading has turned by kMaxHeadingStep
/// since the last kept pose (so that a curve's chords stay close to it: a footprint reaching
/// r metres from the path misses at most r * kMaxHeadingStep^2 / 8 of what it sweeps).
class TrajectoryThinning {
 public:
  /// Largest heading change between two kept poses of a curve, radians.
  static constexpr double kMaxHeadingStep = 0.1;

  /// `spacing` in metres; 0 keeps every pose. Throws InvalidInputError for a negative or
  /// non-finite spacing.
  explicit TrajectoryThinning(double spacing);

  /// The kept poses of `poses`, in order (all of them when the spacing is 0).
  std::vector<TrajectoryPose> apply(const std::vector<TrajectoryPose>& poses) const;

 private:
  double spacing_;
};

}  // namespace kinematic_coverage::core
