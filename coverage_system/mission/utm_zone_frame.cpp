#include "coverage_system/mission/utm_zone_frame.h"

#include <GeographicLib/TransverseMercator.hpp>
#include <GeographicLib/UTMUPS.hpp>
#include <cmath>

#include "coverage_system/mission/local_east_north_frame.h"
#include "polygon_coverage_ros_bridge/base/number_format.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {
namespace {

/// The latitudes UTM covers (degrees); the polar regions use UPS instead.
constexpr double kMinUtmLatitude = -80.0;
constexpr double kMaxUtmLatitude = 84.0;
/// Zone n's central meridian is kZoneWidth * n - kZoneOneCentralMeridianOffset degrees
/// (zone 1: 177 degrees west).
constexpr double kZoneWidth = 6.0;
constexpr double kZoneOneCentralMeridianOffset = 183.0;

}  // namespace

UtmZoneFrame::UtmZoneFrame(const GeoPoint& datum) : datum_(datum) {
  LocalEastNorthFrame::checkRange(datum, "the datum");
  if (datum.latitude < kMinUtmLatitude || datum.latitude >= kMaxUtmLatitude) {
    throw InvalidInputError("the datum (latitude " + formatNumber(datum.latitude) +
                            ") lies outside the latitudes UTM covers, " +
                            formatNumber(kMinUtmLatitude) + " to " + formatNumber(kMaxUtmLatitude) +
                            ": use projection local");
  }
  zone_ = GeographicLib::UTMUPS::StandardZone(datum.latitude, datum.longitude);
  central_meridian_ = kZoneWidth * zone_ - kZoneOneCentralMeridianOffset;
  double x = 0.0, y = 0.0;
  GeographicLib::TransverseMercator::UTM().Forward(central_meridian_, datum.latitude,
                                                   datum.longitude, x, y);
  datum_grid_ = Point2(x, y);
}

std::string UtmZoneFrame::zoneName() const {
  return std::to_string(zone_) + (datum_.latitude >= 0.0 ? "N" : "S");
}

Point2 UtmZoneFrame::toLocal(const GeoPoint& point, const std::string& what) const {
  LocalEastNorthFrame::checkRange(point, what);
  double x = 0.0, y = 0.0, convergence = 0.0, scale = 0.0;
  GeographicLib::TransverseMercator::UTM().Forward(central_meridian_, point.latitude,
                                                   point.longitude, x, y, convergence, scale);
  if (!(std::abs(scale - 1.0) <= kMaxPointScaleError)) {
    throw InvalidInputError(
        what + " lies " + formatNumber(std::round(std::abs(x) / 1000.0)) + " km " +
        (x < 0.0 ? "west" : "east") + " of UTM zone " + zoneName() + "'s central meridian (" +
        formatNumber(central_meridian_) + " degrees), where the projection's point scale is " +
        formatNumber(scale) + ", more than " + formatNumber(kMaxPointScaleError) +
        " from 1: the area is too wide for one UTM zone; plan it in parts");
  }
  return Point2(x, y) - datum_grid_;
}

GeoPoint UtmZoneFrame::toGeographic(const Point2& local) const {
  const Point2 grid = local + datum_grid_;
  GeoPoint point;
  GeographicLib::TransverseMercator::UTM().Reverse(central_meridian_, grid.x(), grid.y(),
                                                   point.latitude, point.longitude);
  return point;
}

}  // namespace kinematic_coverage::core
