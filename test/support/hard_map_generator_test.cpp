#include "test/support/hard_map_generator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>

#include "coverage_system/mission/mission_file_reader.h"
#include "coverage_system/parameters/parameter_schema.h"
#include "coverage_system/parameters/stage_options.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/sweeps/frustum_sensor.h"
#include "polygon_coverage_ros_bridge/validation/polygon_cleaner.h"
#include "polygon_coverage_ros_bridge/validation/polygon_validator.h"
#include "test/support/hard_map_yaml.h"
#include "test/support/random_polygons.h"

namespace kinematic_coverage::core::testing {
namespace {

constexpr int kSeeds = 50;

std::size_t vertexCount(const PolygonWithHoles& polygon) {
  std::size_t count = polygon.hull.size();
  for (const Ring& hole : polygon.holes) count += hole.size();
  return count;
}

bool samePolygon(const PolygonWithHoles& a, const PolygonWithHoles& b) {
  return a.hull == b.hull && a.holes == b.holes;
}

class HardMapGeneratorTest : public ::testing::TestWithParam<MapFamily> {};

// Every map: a valid polygon (holes apart from each other and the hull, except in
// touching_holes, whose holes the cleaner merges or cuts without throwing), at most 600
// vertices, start and goal outside every hole, parameters in range and in the promised
// ranges, the same map for the same seed, and a mission file that reads back to it.
TEST_P(HardMapGeneratorTest, MapsAreValidDeterministicAndInRange) {
  const MapFamily family = GetParam();
  const HardMapGenerator generator(family);
  int cleaned_with_warnings = 0;
  for (int seed = 0; seed < kSeeds; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const HardMap map = generator.generate(seed);
    const Mission& m = map.mission;
    EXPECT_EQ(map.family, family);
    EXPECT_NO_THROW(PolygonValidator().validate(m.polygon));
    EXPECT_LE(vertexCount(m.polygon), HardMapGenerator::kMaxVertices);
    EXPECT_GT(signedArea(m.polygon.hull), 0.0);
    CleanedPolygon cleaned;
    ASSERT_NO_THROW(cleaned = PolygonCleaner().clean(m.polygon));
    if (family == MapFamily::kTouchingHoles) {
      EXPECT_FALSE(m.polygon.holes.empty());
      cleaned_with_warnings += cleaned.warnings.empty() ? 0 : 1;
    } else {
      EXPECT_TRUE(cleaned.warnings.empty()) << cleaned.warnings.front();
      for (std::size_t i = 0; i < m.polygon.holes.size(); ++i) {
        const Ring& hole = m.polygon.holes[i];
        EXPECT_LT(signedArea(hole), 0.0);
        EXPECT_GT(ringDistance(hole, m.polygon.hull), 0.0);
        EXPECT_TRUE(insideRing(hole.front(), m.polygon.hull));
        for (std::size_t j = 0; j < i; ++j) {
          EXPECT_GT(ringDistance(hole, m.polygon.holes[j]), 0.0);
        }
      }
    }
    EXPECT_NO_THROW(PolygonValidator().validateEndpoint("start", m.start, m.polygon));
    EXPECT_NO_THROW(PolygonValidator().validateEndpoint("goal", m.goal, m.polygon));

    const PlannerParameters& p = m.parameters;
    EXPECT_NO_THROW(checkParameters(p));
    const FrustumSensor sensor = sensorOf(p);
    EXPECT_NEAR(sensor.width(), map.footprint_width_m, 1e-9);
    EXPECT_NEAR(sensor.length(), map.footprint_length_m, 1e-9);
    EXPECT_GE(sensor.width(), 1.0 - 1e-9);
    EXPECT_LE(sensor.width(), 13.0 + 1e-9);
    EXPECT_GE(sensor.length(), 1.0 - 1e-9);
    EXPECT_LE(sensor.length(), sensor.width() + 1e-9);
    EXPECT_GE(p.turning_radius, 0.3);
    EXPECT_LE(p.turning_radius, 2.0);
    EXPECT_GE(p.wall_distance, 0.3);
    EXPECT_LE(p.wall_distance, 2.0);

    const HardMap again = generator.generate(seed);
    EXPECT_TRUE(samePolygon(again.mission.polygon, m.polygon));
    EXPECT_EQ(again.mission.start, m.start);
    EXPECT_EQ(again.mission.goal, m.goal);
    EXPECT_EQ(again.mission.parameters.sensor_distance, p.sensor_distance);
    EXPECT_EQ(again.mission.parameters.turning_radius, p.turning_radius);

    const Mission read = MissionFileReader().parse(hardMapYaml(map), "map.yaml");
    EXPECT_TRUE(samePolygon(read.polygon, m.polygon));
    EXPECT_EQ(read.start, m.start);
    EXPECT_EQ(read.goal, m.goal);
    for (const std::string& name : MissionFileReader::parameterNames()) {
      EXPECT_EQ(MissionFileReader::parameterText(read.parameters, name),
                MissionFileReader::parameterText(p, name))
          << name;
    }
  }
  if (family == MapFamily::kTouchingHoles) EXPECT_GE(cleaned_with_warnings, kSeeds / 2);
}

TEST_P(HardMapGeneratorTest, FuzzSizedMapsKeepPlannerFuzzerCaps) {
  if (GetParam() == MapFamily::kStar) GTEST_SKIP() << "the star family has no fuzz size";
  const HardMapGenerator generator(GetParam(), MapSize::kFuzz);
  for (int seed = 0; seed < kSeeds; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const HardMap map = generator.generate(seed);
    EXPECT_NO_THROW(PolygonValidator().validate(map.mission.polygon));
    EXPECT_NO_THROW(PolygonCleaner().clean(map.mission.polygon));
    EXPECT_LE(map.mission.polygon.hull.size(), 12u);
    EXPECT_LE(map.mission.polygon.holes.size(), 2u);
    for (const Ring& hole : map.mission.polygon.holes) EXPECT_LE(hole.size(), 6u);
  }
}

INSTANTIATE_TEST_SUITE_P(Families, HardMapGeneratorTest,
                         ::testing::ValuesIn(HardMapGenerator::families()),
                         [](const auto& info) { return HardMapGenerator::name(info.param); });

TEST(HardMapGenerator, CombTeethStraddleTwoWallDistances) {
  for (int seed = 0; seed < kSeeds; ++seed) {
    const HardMap map = HardMapGenerator(MapFamily::kComb).generate(seed);
    const double two_w = 2.0 * map.mission.parameters.wall_distance;
    const auto& widths = map.passage_widths_m;
    ASSERT_GE(widths.size(), 3u);
    EXPECT_LT(*std::min_element(widths.begin(), widths.end()), two_w) << "seed " << seed;
    EXPECT_GT(*std::max_element(widths.begin(), widths.end()), two_w) << "seed " << seed;
  }
}

TEST(HardMapGenerator, RoomsCorridorsStraddleTwoWallDistances) {
  int narrower = 0;
  int wider = 0;
  for (int seed = 0; seed < kSeeds; ++seed) {
    const HardMap map = HardMapGenerator(MapFamily::kRooms).generate(seed);
    const double two_w = 2.0 * map.mission.parameters.wall_distance;
    ASSERT_EQ(map.passage_widths_m.size(), 1u);
    const double corridor = map.passage_widths_m.front();
    EXPECT_GE(corridor, 0.8 * two_w);
    EXPECT_LE(corridor, 1.25 * two_w);
    (corridor < two_w ? narrower : wider) += 1;
  }
  EXPECT_GE(narrower, kSeeds / 5);
  EXPECT_GE(wider, kSeeds / 5);
}

TEST(HardMapGenerator, ShorelinesAreLongWithCloseIslands) {
  for (int seed = 0; seed < kSeeds; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const HardMap map = HardMapGenerator(MapFamily::kShoreline).generate(seed);
    const std::size_t vertices = vertexCount(map.mission.polygon);
    EXPECT_GE(vertices, 150u);
    EXPECT_LE(vertices, 600u);
    const auto& gaps = map.island_gaps_m;
    ASSERT_FALSE(gaps.empty());
    ASSERT_EQ(gaps.size(), map.mission.polygon.holes.size());
    EXPECT_GT(*std::min_element(gaps.begin(), gaps.end()), 0.0);
    EXPECT_LT(*std::min_element(gaps.begin(), gaps.end()),
              2.0 * map.mission.parameters.wall_distance);
  }
}

TEST(HardMapGenerator, LakeChartsAreValidDeterministicAndOfTheirSize) {
  for (const auto& [shore, islands] : {std::pair<int, int>{500, 10}, {2000, 40}}) {
    SCOPED_TRACE(std::to_string(shore) + " shore vertices");
    const HardMap map = HardMapGenerator::lakeChart(3, shore, islands);
    const PolygonWithHoles& polygon = map.mission.polygon;
    EXPECT_NO_THROW(PolygonValidator().validate(polygon));
    EXPECT_EQ(polygon.hull.size(), static_cast<std::size_t>(shore));
    EXPECT_EQ(polygon.holes.size(), static_cast<std::size_t>(islands));
    for (const Ring& island : polygon.holes) {
      EXPECT_GE(island.size(),
                static_cast<std::size_t>(HardMapGenerator::kLakeChartIslandVertices.first));
      EXPECT_LE(island.size(),
                static_cast<std::size_t>(HardMapGenerator::kLakeChartIslandVertices.second));
      EXPECT_GT(ringDistance(island, polygon.hull), 1.0);
    }
    // About kLakeChartSize across.
    Point2 low = polygon.hull.front(), high = low;
    for (const Point2& p : polygon.hull) {
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
    EXPECT_GT((high - low).maxCoeff(), 0.7 * HardMapGenerator::kLakeChartSize);
    EXPECT_LT((high - low).maxCoeff(), 1.6 * HardMapGenerator::kLakeChartSize);
    EXPECT_NO_THROW(PolygonValidator().validateEndpoint("start", map.mission.start, polygon));
    EXPECT_EQ(hardMapYaml(map), hardMapYaml(HardMapGenerator::lakeChart(3, shore, islands)));
  }
}

TEST(HardMapGenerator, RoughShoresAreValidDeterministicAndRoughAtEveryVertex) {
  const HardMap map = HardMapGenerator::roughShore(3, 2000, 40);
  const PolygonWithHoles& polygon = map.mission.polygon;
  EXPECT_NO_THROW(PolygonValidator().validate(polygon));
  ASSERT_EQ(polygon.hull.size(), 2000u);
  EXPECT_EQ(polygon.holes.size(), 40u);
  // White noise: the radius stays within its band, and neighbours often differ by more than
  // the band's half-width (a smooth shore's radius barely changes between vertices 0.4 m
  // apart).
  const double r = HardMapGenerator::kRoughShoreRadius;
  const double noise = HardMapGenerator::kRoughShoreNoise;
  std::size_t big_jumps = 0;
  for (std::size_t i = 0; i < polygon.hull.size(); ++i) {
    const double radius = polygon.hull[i].norm();
    EXPECT_LE(std::abs(radius - r), noise + 1e-9);
    const double next = polygon.hull[(i + 1) % polygon.hull.size()].norm();
    if (std::abs(next - radius) > noise) ++big_jumps;
  }
  EXPECT_GT(big_jumps, polygon.hull.size() / 5);
  for (const Ring& island : polygon.holes) EXPECT_GT(ringDistance(island, polygon.hull), 1.0);
  EXPECT_NO_THROW(PolygonValidator().validateEndpoint("start", map.mission.start, polygon));
  EXPECT_NO_THROW(PolygonValidator().validateEndpoint("goal", map.mission.goal, polygon));
  EXPECT_EQ(hardMapYaml(map), hardMapYaml(HardMapGenerator::roughShore(3, 2000, 40)));
}

TEST(HardMapGenerator, ArchipelagosAreValidDeterministicAndSpaced) {
  const HardMap map = HardMapGenerator::archipelago(3, 300);
  const PolygonWithHoles& polygon = map.mission.polygon;
  EXPECT_NO_THROW(PolygonValidator().validate(polygon));
  EXPECT_EQ(polygon.hull.size(), 4u);
  ASSERT_EQ(polygon.holes.size(), 300u);
  std::vector<Point2> centres;
  for (const Ring& island : polygon.holes) {
    EXPECT_GE(island.size(),
              static_cast<std::size_t>(HardMapGenerator::kArchipelagoIslandVertices.first));
    EXPECT_LE(island.size(),
              static_cast<std::size_t>(HardMapGenerator::kArchipelagoIslandVertices.second));
    Point2 centre = Point2::Zero();
    for (const Point2& p : island) centre += p / static_cast<double>(island.size());
    for (const Point2& p : island) {
      EXPECT_LE((p - centre).norm(), 2.0 * HardMapGenerator::kArchipelagoIslandRadius.second);
    }
    EXPECT_GT(
        ringDistance(island, polygon.hull),
        HardMapGenerator::kArchipelagoSpacing - HardMapGenerator::kArchipelagoIslandRadius.second);
    centres.push_back(centre);
  }
  // Islands at most two radii across, their centres a spacing apart: no two come nearer
  // than the spacing less two largest radii.
  const double least_gap = HardMapGenerator::kArchipelagoSpacing -
                           2.0 * HardMapGenerator::kArchipelagoIslandRadius.second;
  for (std::size_t i = 0; i < polygon.holes.size(); ++i) {
    for (std::size_t j = i + 1; j < polygon.holes.size(); ++j) {
      if ((centres[i] - centres[j]).norm() > 4.0 * HardMapGenerator::kArchipelagoSpacing) continue;
      EXPECT_GE(ringDistance(polygon.holes[i], polygon.holes[j]), least_gap);
    }
  }
  EXPECT_NO_THROW(PolygonValidator().validateEndpoint("start", map.mission.start, polygon));
  EXPECT_EQ(hardMapYaml(map), hardMapYaml(HardMapGenerator::archipelago(3, 300)));
  EXPECT_EQ(HardMapGenerator::archipelago(5, 2000).mission.polygon.holes.size(), 2000u);
}

TEST(HardMapGenerator, FamiliesHaveNames) {
  for (MapFamily family : HardMapGenerator::families()) {
    EXPECT_EQ(HardMapGenerator::fromName(HardMapGenerator::name(family)), family);
  }
  EXPECT_FALSE(HardMapGenerator::fromName("lake"));
}

TEST(HardMapGenerator, ReadsListsOfFamilyNames) {
  EXPECT_EQ(HardMapGenerator::fromNames("comb,shoreline"),
            (std::vector<MapFamily>{MapFamily::kComb, MapFamily::kShoreline}));
  EXPECT_FALSE(HardMapGenerator::fromNames("comb,lake").has_value());
  EXPECT_FALSE(HardMapGenerator::fromNames("").has_value());
}

}  // namespace
}  // namespace kinematic_coverage::core::testing
