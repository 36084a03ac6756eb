#include "coverage_system/ros/coverage_planner_node.h"

#include <geometry_msgs/PoseArray.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>
#include <visualization_msgs/MarkerArray.h>

#include <chrono>
#include <sstream>
#include <vector>

#include "coverage_system/mission/mission_file_writer.h"
#include "coverage_system/mission/mission_planner.h"
#include "coverage_system/ros/marker_scale.h"
#include "coverage_system/ros/message_conversion.h"
#include "coverage_system/ros/plan_markers.h"
#include "coverage_system/ros/ros_parameter_reader.h"
#include "polygon_coverage_ros_bridge/base/elapsed_seconds.h"
#include "polygon_coverage_ros_bridge/geometry/internal_error.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace kinematic_coverage::nodes {
namespace {

using core::secondsSince;

/// How long a start or goal in another frame waits for its transform.
const ros::Duration kTransformTimeout(0.5);

/// The planner's stages in order, so that a failure names the stage it happened in.
const std::vector<std::string> kStages = {"validate",    "clean", "offset", "decompose", "sweeps",
                                          "transitions", "solve", "path",   "repair"};

std::string nextStage(const std::string& finished) {
  for (std::size_t i = 0; i + 1 < kStages.size(); ++i) {
    if (kStages[i] == finished) return kStages[i + 1];
  }
  return finished.empty() ? kStages.front() : finished;
}

}  // namespace

CoveragePlannerNode::CoveragePlannerNode(const ros::NodeHandle& node,
                                         const ros::NodeHandle& private_node)
    : node_(node), private_node_(private_node), tf_listener_(tf_buffer_) {
  waypoint_publisher_ = node_.advertise<geometry_msgs::PoseArray>("waypoint_list", 1, true);
  marker_publisher_ = private_node_.advertise<visualization_msgs::MarkerArray>("markers", 1, true);
  status_ = NodeStatus(private_node_, "coverage_planner", "plan");
  polygon_subscriber_ = node_.subscribe("polygon", 1, &CoveragePlannerNode::onPolygon, this);
  start_subscriber_ = node_.subscribe("start", 1, &CoveragePlannerNode::onStart, this);
  goal_subscriber_ = node_.subscribe("goal", 1, &CoveragePlannerNode::onGoal, this);
  activate_subscriber_ = node_.subscribe("activate", 1, &CoveragePlannerNode::onActivate, this);
  plan_service_ = private_node_.advertiseService("plan", &CoveragePlannerNode::onPlanService, this);
  save_mission_service_ = private_node_.advertiseService(
      "save_mission", &CoveragePlannerNode::onSaveMissionService, this);
  ROS_INFO("coverage_planner: waiting for polygon, start and goal");
}

void CoveragePlannerNode::onPolygon(
    const kinematic_coverage::PolygonWithHolesStamped::ConstPtr& message) {
  polygon_ = *message;
  ROS_INFO("coverage_planner: polygon received (%zu hull vertices, %zu holes, frame %s)",
           message->polygon.hull.points.size(), message->polygon.holes.size(),
           message->header.frame_id.c_str());
  publishInputMarkers();
  planIfReceiving();
}

void CoveragePlannerNode::onStart(const geometry_msgs::PointStamped::ConstPtr& message) {
  start_ = *message;
  ROS_INFO("coverage_planner: start (%g, %g) received", message->point.x, message->point.y);
  publishInputMarkers();
  planIfReceiving();
}

void CoveragePlannerNode::onGoal(const geometry_msgs::PointStamped::ConstPtr& message) {
  goal_ = *message;
  ROS_INFO("coverage_planner: goal (%g, %g) received", message->point.x, message->point.y);
  publishInputMarkers();
  planIfReceiving();
}

void CoveragePlannerNode::onActivate(const std_msgs::Empty::ConstPtr&) {
  std::string message;
  plan(message);
}

bool CoveragePlannerNode::onPlanService(std_srvs::Trigger::Request&,
                                        std_srvs::Trigger::Response& response) {
  response.success = plan(response.message);
  return true;
}

void CoveragePlannerNode::planIfReceiving() {
  bool plan_on_receive = false;
  try {
    plan_on_receive = readFlagParameter(private_node_, "plan_on_receive", false);
  } catch (const core::InvalidInputError& error) {
    ROS_ERROR("coverage_planner: validate: %s", error.what());
    publishStatus("validate", false, error.what(), 0.0);
    return;
  }
  if (!plan_on_receive || !polygon_ || !start_ || !goal_) return;
  std::string message;
  plan(message);
}

geometry_msgs::PointStamped CoveragePlannerNode::inPolygonFrame(
    const geometry_msgs::PointStamped& point, const std::string& what) const {
  const std::string frame = frameOf(polygon_->header);
  if (frameOf(point.header) == frame) return point;
  try {
    geometry_msgs::PointStamped latest = point;
    latest.header.frame_id = frameOf(point.header);
    latest.header.stamp = ros::Time(0);  // the newest transform: start and goal are places
    return tf_buffer_.transform(latest, frame, kTransformTimeout);
  } catch (const tf2::TransformException& error) {
    throw core::InvalidInputError(what + " is in frame '" + frameOf(point.header) +
                                  "' and no transform to the polygon's frame '" + frame +
                                  "' is available: " + error.what());
  }
}

void CoveragePlannerNode::publishInputMarkers() {
  marker_publisher_.publish(inputMarkers(polygon_ ? &*polygon_ : nullptr,
                                         start_ ? &*start_ : nullptr, goal_ ? &*goal_ : nullptr));
}

core::Mission CoveragePlannerNode::currentMission() const {
  if (!polygon_ || !start_ || !goal_) {
    std::string missing;
    for (const auto& [known, name] : {std::pair<bool, const char*>{polygon_.has_value(), "polygon"},
                                      {start_.has_value(), "start"},
                                      {goal_.has_value(), "goal"}}) {
      if (!known) missing += std::string(missing.empty() ? "" : ", ") + name;
    }
    throw core::InvalidInputError("cannot plan yet: no " + missing + " received");
  }
  core::Mission mission;
  mission.frame_id = frameOf(polygon_->header);
  mission.polygon = fromMessage(polygon_->polygon);
  mission.start = fromMessage(inPolygonFrame(*start_, "start").point);
  mission.goal = fromMessage(inPolygonFrame(*goal_, "goal").point);
  mission.parameters = readPlannerParameters(private_node_);
  return mission;
}

bool CoveragePlannerNode::onSaveMissionService(
    kinematic_coverage::SaveMission::Request& request,
    kinematic_coverage::SaveMission::Response& response) {
  try {
    if (request.path.empty()) throw core::InvalidInputError("no path given");
    core::MissionFileWriter::write(currentMission(), request.path,
                                   "mission saved by coverage_planner");
    response.success = true;
    response.message = request.path;
    ROS_INFO("coverage_planner: mission saved to %s", request.path.c_str());
  } catch (const core::InvalidInputError& error) {
    response.success = false;
    response.message = std::string("mission not saved: ") + error.what();
    ROS_ERROR("coverage_planner: %s", response.message.c_str());
  }
  return true;
}

bool CoveragePlannerNode::plan(std::string& message) {
  const auto start_time = std::chrono::steady_clock::now();
  std::string finished;
  std::string failed_stage;  // the stage an internal error names
  try {
    const core::Mission mission = currentMission();
    const core::PlannedMission planned =
        core::planMission(mission, [&](const core::PlanningStage& stage) {
          finished = stage.name;
          ROS_INFO("coverage_planner: %s: %s (%.3f s)", stage.name.c_str(), stage.summary.c_str(),
                   stage.duration_s);
        });
    for (const std::string& warning : planned.warnings) {
      ROS_WARN("coverage_planner: %s", warning.c_str());
    }
    std_msgs::Header header;
    header.frame_id = mission.frame_id;
    header.stamp = ros::Time::now();
    waypoint_publisher_.publish(toPoseArray(planned.plan.waypoints, header));
    const visualization_msgs::MarkerArray markers =
        planMarkers(planned.free_area, planned.plan, mission.start, mission.goal, header);
    marker_publisher_.publish(markers);
    ROS_INFO("coverage_planner: rviz: %zu marker points", MarkerScale::pointCount(markers));
    std::ostringstream summary;
    summary << planned.plan.waypoints.size() << " waypoints, " << planned.plan.cells.size()
            << " cells, " << planned.plan.path_length_m << " m, time cost "
            << planned.plan.time_cost_s << " s";
    message = summary.str();
    ROS_INFO("coverage_planner: published %s (planning took %.3f s)", message.c_str(),
             planned.planning_time_s);
    publishStatus("plan", true, message, secondsSince(start_time));
    return true;
  } catch (const core::InvalidInputError& error) {
    message = error.what();
  } catch (const core::InternalError& error) {
    message = std::string("internal error: ") + error.what();
    failed_stage = error.stage();
  } catch (const std::exception& error) {
    message = std::string("internal error: ") + error.what();
  }
  const std::string stage = failed_stage.empty() ? nextStage(finished) : failed_stage;
  ROS_ERROR("coverage_planner: %s: %s", stage.c_str(), message.c_str());
  publishStatus(stage, false, message, secondsSince(start_time));
  return false;
}

void CoveragePlannerNode::publishStatus(const std::string& stage, bool success,
                                        const std::string& message, double duration_s) {
  status_.publish(success, message, duration_s,
                  polygon_ ? polygon_->header.frame_id : std::string(), stage);
}

}  // namespace kinematic_coverage::nodes
