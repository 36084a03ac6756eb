#pragma once

namespace kinematic_coverage::core {

/// The plane a geo-referenced mission is planned in (parameter `projection`).
enum class MapProjection {
  /// The local east-north frame at the datum: exact near it, for areas within 50 km.
  kLocal,
  /// The transverse Mercator grid of the datum's UTM zone, for areas of any length
  /// whose point scale stays within 1e-3 of 1.
  kUtm,
};

}  // namespace kinematic_coverage::core
