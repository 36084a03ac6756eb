#include "test/support/survey_lake_generator.h"

#include <cmath>

#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "test/support/hard_map_generator.h"

namespace kinematic_coverage::core {
namespace testing {
namespace {

Ring scaled(const Ring& ring, double factor) {
  Ring result;
  for (const Point2& p : ring) result.push_back(factor * p);
  return result;
}

}  // namespace

Mission SurveyLakeGenerator::generate(std::uint64_t seed, double area_km2) const {
  Mission mission = HardMapGenerator::lakeChart(seed, kShoreVertices, kIslands).mission;
  PolygonWithHoles& polygon = mission.polygon;
  const double factor = std::sqrt(area_km2 * 1e6 / area(polygon));
  polygon.hull = scaled(polygon.hull, factor);
  for (Ring& hole : polygon.holes) hole = scaled(hole, factor);
  mission.start *= factor;
  mission.goal *= factor;
  PlannerParameters& p = mission.parameters;
  p.sensor_model = "line";
  p.lateral_footprint = kSwath;
  p.lateral_overlap = 0.1;
  p.v_max = kSpeed;
  p.yaw_rate_max = kYawRate;
  p.turning_radius = kSpeed / kYawRate;
  p.wall_distance = kWallDistance;
  p.segment_sampling_distance = kSegmentSampling;
  p.arc_sampling_distance = kArcSampling;
  p.trajectory_output_spacing = kOutputSpacing;
  p.mission_depth = kDepth;
  return mission;
}

}  // namespace testing
}  // namespace kinematic_coverage::core
