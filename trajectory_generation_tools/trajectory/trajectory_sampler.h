#pragma once

#include <cstddef>
#include <vector>

#include "trajectory_generation_tools/path/path_primitive.h"
#include "trajectory_generation_tools/trajectory/trajectory_pose.h"

namespace kinematic_coverage::core {

/// Samples a primitive path into trajectory poses (Thesis section 3.3: a pose at a fixed
/// interval along the path, a finer one on arcs; docs/REFERENCE.md, File formats).
class TrajectorySampler {
 public:
  /// At most this many poses; a request for more is refused rather than exhausting memory.
  static constexpr std::size_t kMaxPoses = 20000000;

  /// Sampling intervals: metres on segments and on arcs, radians on rotations. Throws
  /// InvalidInputError unless each is positive and finite.
  TrajectorySampler(double segment_sampling_distance, double arc_sampling_distance,
                    double rotation_sampling_angle);

  /// The poses of `path`, t left at 0 (TrajectoryTiming dates them). Each primitive is cut
  /// into equal pieces no longer than its interval, with a pose at its exact start and end;
  /// a pose shared by two primitives appears once (as the end of the first), so only the
  /// poses of a rotation share a position. Degenerate primitives (isDegenerate) are
  /// skipped; a path of nothing else gives one pose, its first primitive's start. A
  /// heading jump without a rotation keeps both poses at the joint.
  /// Throws InvalidInputError for a path validatePrimitivePath rejects, or one that would
  /// need more than kMaxPoses poses.
  std::vector<TrajectoryPose> sample(const std::vector<PathPrimitive>& path) const;

  /// As above into `poses`, replacing its contents but keeping its capacity, so a caller
  /// sampling repeatedly (replanning, benchmarks) does not pay for fresh memory each time.
  void sample(const std::vector<PathPrimitive>& path, std::vector<TrajectoryPose>& poses) const;

 private:
  /// How many equal pieces primitive `primitive` is cut into.
  std::size_t pieces(const PathPrimitive& primitive) const;
  /// Appends the poses at the ends of pieces first..count of the `count` equal pieces of
  /// primitive `index` (0: its start, count: its end).
  static void appendPoses(const PathPrimitive& primitive, std::size_t index, std::size_t first,
                          std::size_t count, std::vector<TrajectoryPose>& poses);

  double segment_sampling_distance_;
  double arc_sampling_distance_;
  double rotation_sampling_angle_;
};

}  // namespace kinematic_coverage::core
