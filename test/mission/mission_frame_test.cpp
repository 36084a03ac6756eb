#include "coverage_system/mission/mission_frame.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::core {
namespace {

TEST(MissionFrame, TheParametersChooseTheProjection) {
  PlannerParameters parameters;
  const MissionFrame local = MissionFrame::of({47.3769, 8.5417}, parameters);
  EXPECT_EQ(local.projection(), MapProjection::kLocal);
  EXPECT_EQ(local.projectionName(), "local");
  EXPECT_FALSE(local.utmZone());
  parameters.projection = "utm";
  const MissionFrame utm = MissionFrame::of({47.3769, 8.5417}, parameters);
  EXPECT_EQ(utm.projectionName(), "utm");
  EXPECT_EQ(utm.utmZone().value_or(""), "32N");
  EXPECT_EQ(utm.datum().latitude, 47.3769);
}

TEST(MissionFrame, NorthIsUpInTheLocalFrameAndTurnedByTheConvergenceInUtm) {
  const GeoPoint zurich{47.3769, 8.5417};
  const double pi = std::acos(-1.0);
  EXPECT_NEAR(MissionFrame(zurich, MapProjection::kLocal).northDirection(Point2::Zero()), pi / 2,
              1e-6);
  // West of zone 32's central meridian (9 degrees) true north leans east of grid north by
  // the convergence, about (8.5417 - 9) sin(47.3769) degrees.
  const double convergence = (8.5417 - 9.0) * std::sin(47.3769 * pi / 180.0) * pi / 180.0;
  EXPECT_NEAR(MissionFrame(zurich, MapProjection::kUtm).northDirection(Point2::Zero()),
              pi / 2 + convergence, 1e-5);
}

TEST(MissionFrame, BothProjectionsRoundTripASeventyKilometreLakeWithinATenMillionthOfADegree) {
  // WGS84 -> plane -> WGS84 over a 70 km lake (6.15 to 7.05 degrees east) from its centre.
  for (const MapProjection projection : {MapProjection::kLocal, MapProjection::kUtm}) {
    const MissionFrame frame({46.4, 6.6}, projection);
    for (int i = 0; i <= 30; ++i) {
      for (int j = 0; j <= 6; ++j) {
        const GeoPoint point{46.33 + 0.14 * j / 6.0, 6.15 + 0.9 * i / 30.0};
        const GeoPoint back = frame.toGeographic(frame.toLocal(point, "point"));
        EXPECT_NEAR(back.latitude, point.latitude, 1e-7) << frame.projectionName();
        EXPECT_NEAR(back.longitude, point.longitude, 1e-7) << frame.projectionName();
      }
    }
  }
}

TEST(MissionFrame, TheLocalFrameNamesUtmForAreasBeyondItsReach) {
  const MissionFrame local({46.45, 6.55}, MapProjection::kLocal);
  try {
    local.toLocal({46.45, 7.3}, "hull vertex 9");  // 58 km east
    FAIL() << "no error";
  } catch (const InvalidInputError& error) {
    EXPECT_NE(std::string(error.what()).find("set projection: utm"), std::string::npos)
        << error.what();
  }
  EXPECT_NO_THROW(MissionFrame({46.45, 6.55}, MapProjection::kUtm).toLocal({46.45, 7.3}, "v"));
}

}  // namespace
}  // namespace kinematic_coverage::core
