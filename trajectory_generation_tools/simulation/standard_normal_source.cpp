#include "trajectory_generation_tools/simulation/standard_normal_source.h"

#include <cmath>

namespace kinematic_coverage::core {

StandardNormalSource::StandardNormalSource(std::uint32_t seed) : engine_(seed) {}

double StandardNormalSource::uniform() {
  const std::uint64_t high = engine_() >> 5;  // 27 bits
  const std::uint64_t low = engine_() >> 6;   // 26 bits
  const std::uint64_t bits = (high << 26) | low;
  return (static_cast<double>(bits) + 1.0) / 9007199254740992.0;  // (bits + 1) / 2^53
}

double StandardNormalSource::next() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  const double radius = std::sqrt(-2.0 * std::log(uniform()));
  const double angle = 2.0 * M_PI * uniform();
  spare_ = radius * std::sin(angle);
  has_spare_ = true;
  return radius * std::cos(angle);
}

}  // namespace kinematic_coverage::core
