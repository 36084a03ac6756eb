#include "coverage_system/mission/utm_zone_frame.h"

#include <gtest/gtest.h>

#include <GeographicLib/UTMUPS.hpp>
#include <cmath>
#include <random>
#include <string>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "test/support/invalid_input_message.h"

namespace kinematic_coverage::core {
namespace {

using testing::invalidInputMessage;

TEST(UtmZoneFrame, TheDatumIsTheOriginOfItsStandardZone) {
  const UtmZoneFrame zurich({47.3769, 8.5417});
  EXPECT_EQ(zurich.zoneName(), "32N");
  EXPECT_NEAR(zurich.toLocal({47.3769, 8.5417}, "datum").norm(), 0.0, 1e-9);
  EXPECT_EQ(UtmZoneFrame({-33.9, 151.2}).zoneName(), "56S");
  // Norway's exception: Bergen lies in zone 32, not 31.
  EXPECT_EQ(UtmZoneFrame({60.39, 5.32}).zoneName(), "32N");
}

TEST(UtmZoneFrame, DifferencesAreThoseOfTheUtmEastingsAndNorthings) {
  // Against GeographicLib's UTMUPS (false easting and northing, zone chosen by it): the
  // frame's positions are the UTM coordinates less the datum's, within a millimetre.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> offset(-0.4, 0.4);
  for (const GeoPoint datum : {GeoPoint{47.3769, 8.5417}, GeoPoint{-33.9, 151.2},
                               GeoPoint{64.1, -21.9}, GeoPoint{0.1, 32.5}}) {
    const UtmZoneFrame frame(datum);
    int zone = 0;
    bool north = true;
    double datum_easting = 0.0, datum_northing = 0.0;
    GeographicLib::UTMUPS::Forward(datum.latitude, datum.longitude, zone, north, datum_easting,
                                   datum_northing);
    for (int i = 0; i < 50; ++i) {
      const GeoPoint point{datum.latitude + offset(rng), datum.longitude + offset(rng)};
      int point_zone = 0;
      bool point_north = true;
      double easting = 0.0, northing = 0.0;
      GeographicLib::UTMUPS::Forward(point.latitude, point.longitude, point_zone, point_north,
                                     easting, northing, zone);
      if (point_north != north) northing += (north ? -1.0 : 1.0) * 1e7;
      const Point2 local = frame.toLocal(point, "point");
      EXPECT_NEAR(local.x(), easting - datum_easting, 1e-3) << datum.latitude << ", " << i;
      EXPECT_NEAR(local.y(), northing - datum_northing, 1e-3) << datum.latitude << ", " << i;
    }
  }
}

TEST(UtmZoneFrame, PointsRoundTripWithinATenMillionthOfADegree) {
  // Across a 70 km lake, and across the equator without a jump.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> offset(-0.45, 0.45);
  for (const GeoPoint datum : {GeoPoint{46.45, 6.55}, GeoPoint{0.0, 33.0}}) {
    const UtmZoneFrame frame(datum);
    for (int i = 0; i < 200; ++i) {
      const GeoPoint point{datum.latitude + 0.3 * offset(rng), datum.longitude + offset(rng)};
      const GeoPoint back = frame.toGeographic(frame.toLocal(point, "point"));
      EXPECT_NEAR(back.latitude, point.latitude, 1e-7) << i;
      EXPECT_NEAR(back.longitude, point.longitude, 1e-7) << i;
    }
  }
  const UtmZoneFrame equator({0.0, 33.0});
  const Point2 south = equator.toLocal({-0.01, 33.0}, "south");
  const Point2 north = equator.toLocal({0.01, 33.0}, "north");
  // 0.02 degrees of the meridian at the equator, 2211.5 m, at the central scale 0.9996.
  EXPECT_NEAR(north.y() - south.y(), 2210.6, 0.2);
}

TEST(UtmZoneFrame, RefusesPointsWhereThePointScaleIsOffByMoreThanAThousandth) {
  const UtmZoneFrame frame({47.0, 9.0});  // zone 32's central meridian
  // 227 km east of it the point scale is about 1.0002; 380 km east about 1.0014.
  EXPECT_NO_THROW(frame.toLocal({47.0, 12.0}, "vertex"));
  const std::string error = invalidInputMessage([&] {
    frame.toLocal({47.0, 14.0}, "hull vertex 3");
  });
  EXPECT_NE(error.find("hull vertex 3 lies 380 km east of UTM zone 32N's central meridian"),
            std::string::npos)
      << error;
  EXPECT_NE(error.find("point scale is 1.001"), std::string::npos) << error;
  EXPECT_THROW(frame.toLocal({47.0, 191.0}, "vertex"), InvalidInputError);
  const std::string polar = invalidInputMessage([] { UtmZoneFrame({85.0, 10.0}); });
  EXPECT_NE(polar.find("outside the latitudes UTM covers"), std::string::npos) << polar;
  EXPECT_NE(polar.find("use projection local"), std::string::npos) << polar;
}

}  // namespace
}  // namespace kinematic_coverage::core
