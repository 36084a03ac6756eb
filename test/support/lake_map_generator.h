#pragma once

#include <cstdint>

#include "coverage_system/mission/mission.h"

namespace kinematic_coverage::core {
namespace testing {

/// Seeded lake-like maps after the thesis's Chapter 4 experiment (lake_30x30.yaml): a
/// 30 m x 30 m square with two obstacles of other shapes and places (a turned rectangle or
/// a star-shaped polygon of 3 to 7 vertices, 2 to 5 m in radius, at least 2.5 m from the
/// shore and from each other), start [1, 1], goal [29, 29] and the experiment's
/// parameters. The turn-smoothing share of the default strategy is measured on them
/// (bench/smoothing/strategy_benchmark.cpp), so the generator stays fixed: a change of it
/// changes that benchmark's reference maps.
class LakeMapGenerator {
 public:
  /// Side of the square (m).
  static constexpr double kSide = 30.0;

  /// The map of `seed` (std::mt19937 over the seed), the same map for the same seed.
  Mission generate(std::uint64_t seed) const;
};

}  // namespace testing
}  // namespace kinematic_coverage::core
