#pragma once

#include <cstdint>
#include <random>

namespace kinematic_coverage::core {

/// Standard normal draws that are the same on every machine for a seed: the simulator's
/// disturbances are seeded so that its figures can be checked (std::normal_distribution's
/// algorithm is left to the library, std::mt19937's is not).
class StandardNormalSource {
 public:
  explicit StandardNormalSource(std::uint32_t seed);

  /// The next draw of N(0, 1) (Box-Muller on two 53-bit uniforms).
  double next();

 private:
  /// A uniform draw in (0, 1], from two 32-bit outputs of the engine.
  double uniform();

  std::mt19937 engine_;
  bool has_spare_ = false;
  double spare_ = 0.0;
};

}  // namespace kinematic_coverage::core
