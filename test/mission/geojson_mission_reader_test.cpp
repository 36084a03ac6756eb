#include "coverage_system/mission/geojson_mission_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "coverage_system/mission/local_east_north_frame.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"

namespace kinematic_coverage::core {
namespace {

/// A square of about 60 m x 55 m at Zurich with one square hole, as a GIS writes it.
std::string lake(const std::string& properties, const std::string& geometry_type = "Polygon") {
  const std::string rings =
      "[[[8.5410, 47.3760], [8.5418, 47.3760], [8.5418, 47.3765], [8.5410, 47.3765], "
      "[8.5410, 47.3760]], [[8.5413, 47.3762], [8.5414, 47.3762], [8.5414, 47.3763], "
      "[8.5413, 47.3763], [8.5413, 47.3762]]]";
  return R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": )" +
         properties + R"(, "geometry": {"type": ")" + geometry_type + R"(", "coordinates": )" +
         (geometry_type == "MultiPolygon" ? "[" + rings + "]" : rings) +
         R"(}}, {"type": "Feature", "properties": {"role": "start"}, "geometry": {"type": "Point", )"
         R"("coordinates": [8.5411, 47.3761]}}, {"type": "Feature", "properties": {"role": "goal"}, )"
         R"("geometry": {"type": "Point", "coordinates": [8.5417, 47.3764]}}]})";
}

std::string errorOf(const std::string& text) {
  try {
    GeoJsonMissionReader().parse(text, "lake.geojson");
  } catch (const InvalidInputError& error) {
    return error.what();
  }
  return "";
}

TEST(GeoJsonMissionReader, ReadsTheAreaStartGoalAndParametersInTheLocalFrame) {
  const Mission mission = GeoJsonMissionReader().parse(
      lake(R"({"datum": [47.3760, 8.5410], "turning_radius": 0.5, "smoothing_strategy": "local"})"),
      "lake.geojson");
  ASSERT_TRUE(mission.datum.has_value());
  EXPECT_DOUBLE_EQ(mission.datum->latitude, 47.3760);
  EXPECT_EQ(mission.polygon.hull.size(), 4u);  // the closing position dropped
  ASSERT_EQ(mission.polygon.holes.size(), 1u);
  EXPECT_NEAR(mission.polygon.hull.front().norm(), 0.0, 1e-9);  // the datum's corner
  EXPECT_NEAR(area(mission.polygon), 60.4 * 55.6 - 7.5 * 11.1, 3.0);
  EXPECT_GT(mission.start.x(), 0.0);
  EXPECT_GT(mission.goal.y(), mission.start.y());
  EXPECT_EQ(mission.parameters.turning_radius, 0.5);
  EXPECT_EQ(mission.parameters.smoothing_strategy, "local");
  EXPECT_EQ(mission.frame_id, "map");
}

/// A lake `length_km` long east-west at latitude 46.45 (about Lake Geneva's) from
/// `west` degrees of longitude, 2 km wide, its start and goal near its west end.
std::string longLake(double west, double length_km) {
  const double east = west + length_km / (111.32 * std::cos(46.45 * M_PI / 180.0));
  const auto position = [](double longitude, double latitude) {
    if (longitude > 180.0) longitude -= 360.0;
    return "[" + std::to_string(longitude) + ", " + std::to_string(latitude) + "]";
  };
  const std::string ring = "[[" + position(west, 46.44) + ", " + position(east, 46.44) + ", " +
                           position(east, 46.46) + ", " + position(west, 46.46) + ", " +
                           position(west, 46.44) + "]]";
  return R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {}, )"
         R"("geometry": {"type": "Polygon", "coordinates": )" +
         ring + R"(}}, {"type": "Feature", "properties": {"role": "start"}, "geometry": )" +
         R"({"type": "Point", "coordinates": )" + position(west + 0.01, 46.45) +
         R"(}}, {"type": "Feature", "properties": {"role": "goal"}, "geometry": )" +
         R"({"type": "Point", "coordinates": )" + position(west + 0.02, 46.45) + "}}]}";
}

TEST(GeoJsonMissionReader, TheDatumDefaultsToTheCentreOfTheHullsExtent) {
  const Mission mission = GeoJsonMissionReader().parse(lake("{}"), "lake.geojson");
  ASSERT_TRUE(mission.datum.has_value());
  EXPECT_DOUBLE_EQ(mission.datum->latitude, 0.5 * (47.3760 + 47.3765));
  EXPECT_DOUBLE_EQ(mission.datum->longitude, 0.5 * (8.5410 + 8.5418));
  // A 73 km lake: its ends lie 50 km from one end, which a local frame is not made for,
  // and 36.5 km from its centre.
  EXPECT_NO_THROW(GeoJsonMissionReader().parse(longLake(6.2, 73.0), "geneva.geojson"));
  const std::string from_its_end = R"({"datum": [46.44, 6.2]})";
  std::string anchored = longLake(6.2, 73.0);
  anchored.replace(anchored.find("{}"), 2, from_its_end);
  EXPECT_THROW(GeoJsonMissionReader().parse(anchored, "geneva.geojson"), InvalidInputError);
  // Across the antimeridian the extent is the short one: its centre lies near 180.
  const Mission pacific = GeoJsonMissionReader().parse(longLake(179.8, 30.0), "pacific.geojson");
  EXPECT_GT(std::abs(pacific.datum->longitude), 179.9);
  const Mission multi = GeoJsonMissionReader().parse(lake("{}", "MultiPolygon"), "lake.geojson");
  EXPECT_NEAR(area(multi.polygon), area(mission.polygon), 1e-6);
  EXPECT_EQ(multi.polygon.holes.size(), 1u);
}

TEST(GeoJsonMissionReader, PlansLongLakesInUtmAndNamesTheExtentOfAnAreaTooLarge) {
  // 150 km: beyond a local frame's reach from any datum, within one UTM zone.
  std::string long_lake = longLake(6.2, 150.0);
  const std::string local_error = errorOf(long_lake);
  EXPECT_NE(local_error.find("set projection: utm"), std::string::npos) << local_error;
  EXPECT_NE(local_error.find("the area spans 150 km east-west and 2 km north-south"),
            std::string::npos)
      << local_error;
  long_lake.replace(long_lake.find("{}"), 2, R"({"projection": "utm"})");
  const Mission utm = GeoJsonMissionReader().parse(long_lake, "long.geojson");
  EXPECT_EQ(utm.parameters.projection, "utm");
  // The hull's east-west extent, 150 km, within the grid's scale (1e-3) and its turn.
  double west = INFINITY, east = -INFINITY;
  for (const Point2& p : utm.polygon.hull) {
    west = std::min(west, p.x());
    east = std::max(east, p.x());
  }
  EXPECT_NEAR((east - west) / 150000.0, 1.0, 2e-3);
  // 800 km across two zones: the point scale of the datum's zone is off by more than 1e-3.
  std::string wide = longLake(3.0, 800.0);
  wide.replace(wide.find("{}"), 2, R"({"projection": "utm"})");
  const std::string wide_error = errorOf(wide);
  EXPECT_NE(wide_error.find("point scale"), std::string::npos) << wide_error;
  EXPECT_NE(wide_error.find("the area spans 799 km east-west"), std::string::npos) << wide_error;
}

TEST(GeoJsonMissionReader, AGivenDatumAnchorsTheFrameInsteadOfTheFiles) {
  const GeoPoint given{47.3750, 8.5400};
  const Mission anchored =
      GeoJsonMissionReader(given).parse(lake(R"({"datum": [47.3760, 8.5410]})"), "lake.geojson");
  const Mission written =
      GeoJsonMissionReader().parse(lake(R"({"datum": [47.3750, 8.5400]})"), "lake.geojson");
  ASSERT_TRUE(anchored.datum.has_value());
  EXPECT_EQ(anchored.datum->latitude, given.latitude);
  EXPECT_EQ(anchored.datum->longitude, given.longitude);
  EXPECT_EQ(anchored.polygon.hull, written.polygon.hull);
  EXPECT_EQ(anchored.start, written.start);
  // The hull's first corner lies about 111 m north and 75 m east of the given datum.
  EXPECT_NEAR(anchored.polygon.hull.front().y(), 111.2, 0.5);
  EXPECT_NEAR(anchored.polygon.hull.front().x(), 75.4, 0.5);
  try {
    GeoJsonMissionReader(GeoPoint{91.0, 8.5}).parse(lake("{}"), "lake.geojson");
    FAIL() << "a latitude of 91 degrees was taken";
  } catch (const InvalidInputError& error) {
    EXPECT_NE(std::string(error.what()).find("91"), std::string::npos) << error.what();
  }
}

TEST(GeoJsonMissionReader, NamesEachProblem) {
  EXPECT_NE(errorOf("[1, 2]").find("not a GeoJSON FeatureCollection"), std::string::npos);
  EXPECT_NE(errorOf(R"({"type": "FeatureCollection", "features": []})").find("no Polygon"),
            std::string::npos);
  EXPECT_NE(errorOf(lake(R"({"depth": 2})")).find("unknown parameter 'depth'"), std::string::npos);
  // A parameter's error names the feature whose properties hold it.
  EXPECT_EQ(errorOf(lake(R"({"turning_radius": -1})")),
            "lake.geojson: features[0].properties: turning_radius = -1 is out of range: it must "
            "be a finite number > 0 (m)");
  EXPECT_EQ(errorOf(lake(R"({"smoothing": "often"})")),
            "lake.geojson: features[0].properties: smoothing: the value 'often' is not true or "
            "false");
  EXPECT_NE(errorOf(lake(R"({"datum": [47.3760]})")).find("[latitude, longitude]"),
            std::string::npos);
  std::string line = lake("{}");
  line.replace(line.find("\"Polygon\""), 9, "\"LineString\"");
  EXPECT_NE(errorOf(line).find("a LineString geometry"), std::string::npos);
  EXPECT_TRUE(GeoJsonMissionReader::isGeoJsonPath("charts/Lake.GeoJSON"));
  EXPECT_FALSE(GeoJsonMissionReader::isGeoJsonPath("missions/lake.yaml"));
}

}  // namespace
}  // namespace kinematic_coverage::core
