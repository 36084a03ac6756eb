#include "coverage_system/mission/local_east_north_frame.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {
namespace {

TEST(LocalEastNorthFrame, TheDatumIsTheOriginAndAxesPointEastAndNorth) {
  const LocalEastNorthFrame frame({47.3769, 8.5417});
  const Point2 origin = frame.toLocal({47.3769, 8.5417}, "datum");
  EXPECT_NEAR(origin.norm(), 0.0, 1e-9);
  // A thousandth of a degree east and north: about 75.5 m and 111.2 m at 47.4 degrees north.
  const Point2 east = frame.toLocal({47.3769, 8.5427}, "east");
  const Point2 north = frame.toLocal({47.3779, 8.5417}, "north");
  EXPECT_NEAR(east.x(), 75.5, 0.2);
  EXPECT_NEAR(east.y(), 0.0, 0.01);
  EXPECT_NEAR(north.x(), 0.0, 1e-6);
  EXPECT_NEAR(north.y(), 111.2, 0.2);
}

TEST(LocalEastNorthFrame, PointsRoundTripWithinAMicrometre) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> offset(-20000.0, 20000.0);
  for (const GeoPoint datum : {GeoPoint{47.3769, 8.5417}, GeoPoint{-33.9, 151.2},
                               GeoPoint{64.1, -21.9}, GeoPoint{0.0, 179.99}}) {
    const LocalEastNorthFrame frame(datum);
    for (int i = 0; i < 200; ++i) {
      const Point2 local(offset(rng), offset(rng));
      const Point2 back = frame.toLocal(frame.toGeographic(local), "point");
      EXPECT_NEAR((back - local).norm(), 0.0, 1e-6) << datum.latitude << ", " << i;
    }
  }
}

TEST(LocalEastNorthFrame, RejectsCoordinatesOutOfRangeAndAreasTooLarge) {
  EXPECT_THROW(LocalEastNorthFrame({91.0, 0.0}), InvalidInputError);
  EXPECT_THROW(LocalEastNorthFrame({0.0, std::nan("")}), InvalidInputError);
  const LocalEastNorthFrame frame({47.0, 8.0});
  EXPECT_THROW(frame.toLocal({47.0, 181.0}, "vertex"), InvalidInputError);
  EXPECT_THROW(frame.toLocal({47.0, 9.0}, "vertex"), InvalidInputError);  // 76 km east
  EXPECT_NO_THROW(frame.toLocal({47.0, 8.5}, "vertex"));                  // 38 km east
}

}  // namespace
}  // namespace kinematic_coverage::core
