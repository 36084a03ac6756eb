#pragma once

#include <memory>

#include "coverage_system/mission/mission.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// The local east-north frame of a geo-referenced mission (metres; x east, y north) at a
/// datum on the WGS84 ellipsoid, by GeographicLib's LocalCartesian (exact, not a map
/// projection), its up coordinate dropped: at the kMaxRadius a lake can have, the surface
/// falls less than 200 m below the frame's plane, and horizontal distances differ from it
/// by well under a part in ten thousand.
class LocalEastNorthFrame {
 public:
  /// Farthest a mission's point may be from the datum (m): larger areas need a map
  /// projection, not a local frame.
  static constexpr double kMaxRadius = 50000.0;

  /// Throws InvalidInputError for a datum outside [-90, 90] x [-180, 180] or not finite.
  explicit LocalEastNorthFrame(const GeoPoint& datum);
  ~LocalEastNorthFrame();
  LocalEastNorthFrame(const LocalEastNorthFrame& other);
  LocalEastNorthFrame& operator=(const LocalEastNorthFrame& other);

  const GeoPoint& datum() const { return datum_; }

  /// The local position of `point`. Throws InvalidInputError, naming the point `what`, for
  /// a latitude or longitude out of range or a point farther than kMaxRadius from the datum.
  Point2 toLocal(const GeoPoint& point, const std::string& what) const;

  /// The geographic position of a local point (on the ellipsoid below it).
  GeoPoint toGeographic(const Point2& local) const;

  /// Throws InvalidInputError, naming the point `what`, for a latitude outside [-90, 90], a
  /// longitude outside [-180, 180] or a coordinate that is not finite.
  static void checkRange(const GeoPoint& point, const std::string& what);

 private:
  struct Projection;
  GeoPoint datum_;
  std::unique_ptr<Projection> projection_;
};

}  // namespace kinematic_coverage::core
