// The mission_publisher node (docs/REFERENCE.md, Nodes and topics): publishes the polygon,
// start and goal of the mission file named by `~mission`, latched, in the mission's frame,
// so that a launch file can run a mission without anyone publishing by hand. A GeoJSON
// mission is published in metres east and north of `~datum` ([latitude, longitude]) when
// that is set, else of the file's datum.

#include <geometry_msgs/PointStamped.h>
#include <ros/ros.h>

#include <optional>
#include <string>

#include "coverage_system/mission/read_mission.h"
#include "coverage_system/ros/message_conversion.h"
#include "coverage_system/ros/ros_parameter_reader.h"
#include "kinematic_coverage/PolygonWithHolesStamped.h"
#include "polygon_coverage_ros_bridge/geometry/invalid_input_error.h"

namespace {

geometry_msgs::PointStamped pointMessage(const kinematic_coverage::core::Point2& point,
                                         const std_msgs::Header& header) {
  geometry_msgs::PointStamped message;
  message.header = header;
  message.point.x = point.x();
  message.point.y = point.y();
  return message;
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "mission_publisher");
  ros::NodeHandle node;
  ros::NodeHandle private_node("~");
  std::string path;
  kinematic_coverage::core::Mission mission;
  try {
    path = kinematic_coverage::nodes::readStringParameter(private_node, "mission", "");
    if (path.empty()) {
      ROS_ERROR("mission_publisher: the parameter ~mission (a mission file) is not set");
      return 2;
    }
    const std::optional<kinematic_coverage::core::GeoPoint> datum =
        kinematic_coverage::nodes::readGeoPointParameter(private_node, "datum");
    mission = kinematic_coverage::core::readMission(path, {}, {}, datum);
    if (datum && !mission.datum) {
      ROS_WARN("mission_publisher: ~datum is for GeoJSON missions; %s is in metres already",
               path.c_str());
    }
  } catch (const kinematic_coverage::core::InvalidInputError& error) {
    ROS_ERROR("mission_publisher: %s", error.what());
    return 2;
  }
  ros::Publisher polygon_publisher =
      node.advertise<kinematic_coverage::PolygonWithHolesStamped>("polygon", 1, true);
  ros::Publisher start_publisher = node.advertise<geometry_msgs::PointStamped>("start", 1, true);
  ros::Publisher goal_publisher = node.advertise<geometry_msgs::PointStamped>("goal", 1, true);
  std_msgs::Header header;
  header.frame_id = mission.frame_id;
  header.stamp = ros::Time::now();
  polygon_publisher.publish(kinematic_coverage::nodes::toMessage(mission.polygon, header));
  start_publisher.publish(pointMessage(mission.start, header));
  goal_publisher.publish(pointMessage(mission.goal, header));
  ROS_INFO("mission_publisher: published %s (%zu hull vertices, %zu holes, frame %s)", path.c_str(),
           mission.polygon.hull.size(), mission.polygon.holes.size(), mission.frame_id.c_str());
  if (mission.datum) {
    ROS_INFO(
        "mission_publisher: a GeoJSON mission, in metres east and north of its datum "
        "(%.9f, %.9f)",
        mission.datum->latitude, mission.datum->longitude);
  }
  ros::spin();
  return 0;
}
