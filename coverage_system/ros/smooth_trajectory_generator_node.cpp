#include "coverage_system/ros/smooth_trajectory_generator_node.h"

#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <visualization_msgs/MarkerArray.h>

#include <chrono>
#include <optional>
#include <sstream>
#include <vector>

#include "coverage_system/mission/trajectory_coverage.h"
#include "coverage_system/mission/trajectory_pipeline.h"
#include "coverage_system/mission/wall_clearance_warning.h"
#include "coverage_system/parameters/stage_options.h"
#include "coverage_system/planner/reachable_offset_parts.h"
#include "coverage_system/ros/heatmap_grid.h"
#include "coverage_system/ros/marker_scale.h"
#include "coverage_system/ros/message_conversion.h"
#include "coverage_system/ros/ros_parameter_reader.h"
#include "coverage_system/ros/trajectory_markers.h"
#include "polygon_coverage_ros_bridge/base/elapsed_seconds.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"
#include "polygon_coverage_ros_bridge/geometry/planar_geometry.h"
#include "polygon_coverage_ros_bridge/validation/free_area_builder.h"
#include "polygon_coverage_ros_bridge/validation/polygon_cleaner.h"
#include "trajectory_generation_tools/trajectory/trajectory_thinning.h"

namespace kinematic_coverage::nodes {

using core::secondsSince;

namespace {

/// m on a map of MarkerScale::kReferenceExtent: the spacing of the poses of the displayed
/// path (`~path`), and the closest approach's sphere.
constexpr double kPathDisplaySpacing = 0.05;
constexpr double kClosestApproachSize = 0.6;

}  // namespace

SmoothTrajectoryGeneratorNode::SmoothTrajectoryGeneratorNode(const ros::NodeHandle& node,
                                                             const ros::NodeHandle& private_node)
    : node_(node), private_node_(private_node) {
  trajectory_publisher_ = node_.advertise<geometry_msgs::PoseArray>("trajectory", 1, true);
  path_publisher_ = node_.advertise<nav_msgs::Path>("trajectory_path", 1, true);
  marker_publisher_ = private_node_.advertise<visualization_msgs::MarkerArray>("markers", 1, true);
  heatmap_publisher_ =
      private_node_.advertise<nav_msgs::OccupancyGrid>("coverage_heatmap", 1, true);
  status_ = NodeStatus(private_node_, "smooth_trajectory_generator", "smooth");
  polygon_subscriber_ =
      node_.subscribe("polygon", 1, &SmoothTrajectoryGeneratorNode::onPolygon, this);
  updated_polygon_subscriber_ =
      node_.subscribe("updated_polygon", 1, &SmoothTrajectoryGeneratorNode::onPolygon, this);
  waypoint_subscriber_ =
      node_.subscribe("waypoint_list", 1, &SmoothTrajectoryGeneratorNode::onWaypoints, this);
  ROS_INFO("smooth_trajectory_generator: waiting for a polygon and a waypoint_list");
}

void SmoothTrajectoryGeneratorNode::onPolygon(
    const kinematic_coverage::PolygonWithHolesStamped::ConstPtr& message) {
  const auto start = std::chrono::steady_clock::now();
  const std::string frame = frameOf(message->header);
  ROS_INFO("smooth_trajectory_generator: polygon received (%zu holes, frame %s)",
           message->polygon.holes.size(), frame.c_str());
  // An invalid polygon is forgotten: smoothing against the one before could cross the
  // obstacles it moved.
  free_area_.reset();
  try {
    const core::PolygonWithHoles raw = fromMessage(message->polygon);
    core::CleanedPolygon cleaned =
        core::FreeAreaBuilder(core::boundarySimplificationOf(readPlannerParameters(private_node_)))
            .build(raw)
            .cleaned;
    for (const std::string& warning : cleaned.warnings) {
      ROS_WARN("smooth_trajectory_generator: %s", warning.c_str());
    }
    free_area_ = std::move(cleaned.free_area);
    polygon_frame_ = frame;
  } catch (const core::InvalidInputError& error) {
    status_.reject(std::string("polygon: ") + error.what(), secondsSince(start), frame);
    return;
  } catch (const std::exception& error) {
    status_.reject(std::string("internal error: polygon: ") + error.what(), secondsSince(start),
                   frame);
    return;
  }
  if (waypoints_) generate();
}

void SmoothTrajectoryGeneratorNode::onWaypoints(const geometry_msgs::PoseArray::ConstPtr& message) {
  const auto start = std::chrono::steady_clock::now();
  const std::string frame = frameOf(message->header);
  ROS_INFO("smooth_trajectory_generator: waypoint_list of %zu waypoints received",
           message->poses.size());
  waypoints_.reset();
  try {
    if (message->poses.empty()) {
      throw core::InvalidInputError("waypoint_list has no poses: a trajectory needs at least one");
    }
    waypoints_ = checkedPoses(*message, "waypoint");
    waypoint_frame_ = frame;
  } catch (const core::InvalidInputError& error) {
    status_.reject(std::string("waypoint_list: ") + error.what(), secondsSince(start), frame);
    return;
  }
  if (!free_area_) {
    ROS_INFO("smooth_trajectory_generator: waiting for a polygon to smooth against");
    return;
  }
  generate();
}

void SmoothTrajectoryGeneratorNode::generate() {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<core::Pose2> waypoints = std::move(*waypoints_);
  waypoints_.reset();
  std::string message;
  try {
    if (polygon_frame_ != waypoint_frame_) {
      throw core::InvalidInputError("waypoint_list is in frame '" + waypoint_frame_ +
                                    "' but the polygon is in frame '" + polygon_frame_ + "'");
    }
    const core::PlannerParameters parameters = readPlannerParameters(private_node_);
    // What the trajectory leaves unseen of the area it could search is measured as
    // `coverage_tool plan` measures it, and said as loudly.
    const std::vector<core::PolygonWithHoles> exact_parts =
        core::reachableOffset(*free_area_, core::planningOptionsOf(parameters),
                              waypoints.front().position())
            .exact_parts;
    const core::MeasuredTrajectory measured =
        core::TrajectoryPipeline(parameters, exact_parts, core::WaypointOrigin::kUser)
            .run(waypoints, *free_area_);
    const core::GeneratedTrajectory& trajectory = measured.trajectory;
    std_msgs::Header header;
    header.frame_id = polygon_frame_;
    header.stamp = ros::Time::now();
    trajectory_publisher_.publish(toPoseArray(trajectory.poses, header));
    // rviz's Path display draws every pose: a pose per kPathDisplayShare of the map's extent
    // (and every primitive's ends) draws the same picture at a lake's scale.
    const MarkerScale scale(free_area_->hull);
    const std::vector<core::TrajectoryPose> shown =
        core::TrajectoryThinning(scale.size(kPathDisplaySpacing)).apply(trajectory.poses);
    path_publisher_.publish(toPath(shown, header));
    visualization_msgs::MarkerArray markers = trajectoryMarkers(trajectory.path, header);
    if (!core::keepsClearance(trajectory.min_obstacle_clearance_m, parameters.wall_distance)) {
      const visualization_msgs::MarkerArray closest = closestApproachMarkers(
          trajectory.closest_approach, trajectory.min_obstacle_clearance_m,
          parameters.wall_distance, header, scale.size(kClosestApproachSize));
      markers.markers.insert(markers.markers.end(), closest.markers.begin(), closest.markers.end());
    }
    marker_publisher_.publish(markers);
    const nav_msgs::OccupancyGrid heatmap =
        heatmapGrid(*free_area_, measured.poses, parameters, header);
    heatmap_publisher_.publish(heatmap);
    ROS_INFO(
        "smooth_trajectory_generator: rviz: %zu marker points, path of %zu poses, heatmap "
        "of %u x %u cells",
        MarkerScale::pointCount(markers), shown.size(), heatmap.info.width, heatmap.info.height);
    const core::SmoothingStatistics& turns = trajectory.statistics;
    std::ostringstream summary;
    summary << turns.turns_smoothed << " of " << turns.turns_total << " turns smoothed (inner "
            << turns.inner << ", outer bisector " << turns.outer_bisector << ", outer tangent "
            << turns.outer_tangent << ", reverse curve " << turns.reverse_curve << ", bulb "
            << turns.bulb << "; kept sharp for coverage " << turns.kept_for_coverage << "), "
            << trajectory.poses.size() << " poses, " << trajectory.trajectory_length_m << " m, "
            << trajectory.traversal_time_s << " s";
    const core::TrajectoryCoverage& coverage = measured.coverage;
    summary << "; " << core::coverageSummary(coverage);
    for (const std::optional<std::string>& warning :
         {core::reachableCoverageWarning(coverage), core::smoothingLossWarning(coverage),
          core::wallClearanceWarning(trajectory.min_obstacle_clearance_m, parameters)}) {
      if (!warning) continue;
      ROS_WARN("smooth_trajectory_generator: %s", warning->c_str());
      summary << "; warning: " << *warning;
    }
    const double duration_s = secondsSince(start);
    ROS_INFO("smooth_trajectory_generator: smooth: %s (%.3f s)", summary.str().c_str(), duration_s);
    status_.publish(true, summary.str(), duration_s, header.frame_id);
    return;
  } catch (const core::InvalidInputError& error) {
    message = error.what();
  } catch (const std::exception& error) {
    message = std::string("internal error: ") + error.what();
  }
  status_.reject(message, secondsSince(start), waypoint_frame_);
}

}  // namespace kinematic_coverage::nodes
