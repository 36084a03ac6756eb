#include "test/support/lake_map_generator.h"

#include <gtest/gtest.h>

#include "coverage_system/mission/mission_planner.h"
#include "coverage_system/parameters/parameter_schema.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/validation/polygon_validator.h"
#include "test/support/random_polygons.h"

namespace kinematic_coverage::core::testing {
namespace {

/// The lake maps the strategy benchmark measures.
constexpr int kBenchmarkLakes = 10;

// Every lake: the 30 m square, two clockwise obstacles at least 2.5 m from the shore and
// from each other, start and goal free, valid parameters, the same map for the same seed,
// and a plan.
TEST(LakeMapGenerator, MapsAreValidDeterministicAndPlan) {
  const LakeMapGenerator generator;
  for (int seed = 1; seed <= kBenchmarkLakes; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Mission m = generator.generate(seed);
    ASSERT_EQ(m.polygon.holes.size(), 2u);
    EXPECT_NO_THROW(PolygonValidator().validate(m.polygon));
    EXPECT_DOUBLE_EQ(signedArea(m.polygon.hull), 900.0);
    for (const Ring& hole : m.polygon.holes) {
      EXPECT_LT(signedArea(hole), 0.0);
      EXPECT_GT(ringDistance(hole, m.polygon.hull), 2.5);
    }
    EXPECT_GT(ringDistance(m.polygon.holes[0], m.polygon.holes[1]), 2.5);
    EXPECT_NO_THROW(PolygonValidator().validateEndpoint("start", m.start, m.polygon));
    EXPECT_NO_THROW(PolygonValidator().validateEndpoint("goal", m.goal, m.polygon));
    EXPECT_NO_THROW(checkParameters(m.parameters));
    const Mission again = generator.generate(seed);
    EXPECT_EQ(again.polygon.holes, m.polygon.holes);
    PlannedMission planned;
    ASSERT_NO_THROW(planned = planMission(m));
    EXPECT_GT(planned.plan.waypoints.size(), 2u);
  }
}

// Other seeds give other obstacles.
TEST(LakeMapGenerator, SeedsGiveOtherObstacles) {
  const LakeMapGenerator generator;
  EXPECT_NE(generator.generate(1).polygon.holes, generator.generate(2).polygon.holes);
}

}  // namespace
}  // namespace kinematic_coverage::core::testing
