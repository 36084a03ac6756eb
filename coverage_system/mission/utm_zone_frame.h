#pragma once

#include <string>

#include "coverage_system/mission/mission.h"
#include "polygon_coverage_ros_bridge/geometry/polygon_with_holes.h"

namespace kinematic_coverage::core {

/// The grid of the datum's UTM zone (GeographicLib's UTMUPS zone and transverse Mercator),
/// moved so that the datum is the origin: x and y are the UTM easting and northing minus
/// the datum's, in metres along the grid's east and north, which differ from true east and
/// north by the meridian convergence. Unlike a local frame it has no distance limit; it
/// refuses points where the projection's point scale differs from 1 by more than
/// kMaxPointScaleError, since lengths planned there would be off by more than that share.
class UtmZoneFrame {
 public:
  /// Largest |point scale - 1| a mission's point may have.
  static constexpr double kMaxPointScaleError = 1e-3;

  /// Throws InvalidInputError for a datum out of range or outside UTM's latitudes
  /// (-80 to 84 degrees; the polar regions have no zone).
  explicit UtmZoneFrame(const GeoPoint& datum);

  const GeoPoint& datum() const { return datum_; }

  /// The zone and the datum's hemisphere, e.g. "32N".
  std::string zoneName() const;

  /// The grid position of `point`. Throws InvalidInputError, naming the point `what`, for
  /// a latitude or longitude out of range or a point whose point scale differs from 1 by
  /// more than kMaxPointScaleError (too far east or west of the zone's central meridian).
  Point2 toLocal(const GeoPoint& point, const std::string& what) const;

  /// The geographic position of a grid point.
  GeoPoint toGeographic(const Point2& local) const;

 private:
  GeoPoint datum_;
  int zone_ = 0;
  double central_meridian_ = 0.0;
  /// The datum's transverse Mercator position, without false easting or northing.
  Point2 datum_grid_ = Point2::Zero();
};

}  // namespace kinematic_coverage::core
