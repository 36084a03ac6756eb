#pragma once

#include <cstdint>

#include "coverage_system/mission/mission.h"

namespace kinematic_coverage::core {
namespace testing {

/// Seeded lakes of a chosen area for surveys at lake scale: HardMapGenerator's lake chart
/// (a shore noisy at every scale, warped into bays and headlands, with islands) scaled to
/// the area, and the parameters of a survey vehicle with a side-scan-like line sensor.
/// Their sources: swaths of 100 to 300 m at 2 m/s are what side-scan sonar surveys of lakes
/// by AUVs use; the turning radius is that speed over a 0.1 rad/s yaw rate; 20 m from the
/// shore keeps a vehicle with a few metres of position error off it; a 10 m survey depth.
class SurveyLakeGenerator {
 public:
  static constexpr int kShoreVertices = 1000;
  static constexpr int kIslands = 20;
  static constexpr double kSwath = 150.0;           ///< lateral_footprint, m
  static constexpr double kSpeed = 2.0;             ///< v_max, m/s
  static constexpr double kYawRate = 0.1;           ///< yaw_rate_max, rad/s
  static constexpr double kWallDistance = 20.0;     ///< m
  static constexpr double kSegmentSampling = 10.0;  ///< segment_sampling_distance, m
  static constexpr double kArcSampling = 2.0;       ///< arc_sampling_distance, m
  static constexpr double kOutputSpacing = 100.0;   ///< trajectory_output_spacing, m
  static constexpr double kDepth = 10.0;            ///< mission_depth, m

  /// The lake of `seed` whose free area (shore less islands) is `area_km2` square
  /// kilometres, in metres about its centre; start and goal on its free area.
  Mission generate(std::uint64_t seed, double area_km2) const;
};

}  // namespace testing
}  // namespace kinematic_coverage::core
