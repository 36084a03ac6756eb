#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"

#include <gtest/gtest.h>

#include <cmath>

#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

TEST(FrustumSensor, ThesisFootprint) {
  const FrustumSensor sensor = sensorOf(PlannerParameters{});
  EXPECT_NEAR(sensor.width(), 2 * 3.0 * std::tan(2.27 / 2), 1e-12);   // 12.9 m
  EXPECT_NEAR(sensor.length(), 2 * 3.0 * std::tan(0.52 / 2), 1e-12);  // 1.6 m
  EXPECT_NEAR(sensor.sweepDistance(), 0.6 * sensor.width(), 1e-12);
}

TEST(FrustumSensor, LineSensorHasNoOnwardExtent) {
  PlannerParameters parameters;
  parameters.sensor_model = "line";
  parameters.lateral_footprint = 4.0;
  parameters.lateral_overlap = 0.25;
  const FrustumSensor sensor = sensorOf(parameters);
  EXPECT_DOUBLE_EQ(sensor.width(), 4.0);
  EXPECT_DOUBLE_EQ(sensor.length(), 0.0);
  EXPECT_DOUBLE_EQ(sensor.sweepDistance(), 3.0);
}

TEST(FrustumSensor, FootprintIsCentredRotatedRectangle) {
  const FrustumSensor sensor(4.0, 2.0, 0.0);
  const Ring footprint = sensor.footprint({1.0, 2.0, M_PI / 2});
  EXPECT_NEAR(signedArea(footprint), 8.0, 1e-12);
  // Heading +y: 2 m along y, 4 m across (along x).
  for (const Point2& corner : footprint) {
    EXPECT_NEAR(std::abs(corner.x() - 1.0), 2.0, 1e-12);
    EXPECT_NEAR(std::abs(corner.y() - 2.0), 1.0, 1e-12);
  }
}

}  // namespace
}  // namespace kinematic_coverage::core
